"""A structured grid of quadrilaterals as a UCD file, shared by the mesh
scripts (make_distorted_grid.py, make_quarter_annulus.py,
make_strip_footing_grid.py). Node (i, j), 0 <= i <= nx, is number
j (nx + 1) + i + 1 (i fastest); cell (i, j) has the nodes (i, j),
(i+1, j), (i+1, j+1), (i, j+1), counter-clockwise when i runs along the
first direction (x, r) and j along the second (y, theta). Boundary faces
are UCD "line" cells, whose material id deal.II's GridIn::read_ucd takes
as the face's boundary id."""


def write(path, points, nx, rows, side_ids=None, number="{:.15g}"):
    """Writes the first `rows` rows of cells of the grid whose node
    coordinates `points` are listed j-major (i fastest). With `side_ids`,
    the boundary ids of the sides (i = 0, i = nx, j = 0, j = rows), also
    the boundary lines: those of i = 0 and i = nx for each j, then those of
    j = 0 and j = rows for each i. `number` formats a coordinate."""
    node = lambda i, j: j * (nx + 1) + i + 1
    lines = []
    if side_ids:
        first, last, bottom, top = side_ids
        for j in range(rows):
            lines.append((first, node(0, j), node(0, j + 1)))
            lines.append((last, node(nx, j), node(nx, j + 1)))
        for i in range(nx):
            lines.append((bottom, node(i, 0), node(i + 1, 0)))
            lines.append((top, node(i, rows), node(i + 1, rows)))
    n_nodes = (rows + 1) * (nx + 1)
    with open(path, "w") as f:
        f.write(f"{n_nodes} {nx * rows + len(lines)} 0 0 0\n")
        for k, (x, y) in enumerate(points[:n_nodes]):
            f.write(f"{k + 1} {number.format(x)} {number.format(y)} 0\n")
        c = 0
        for j in range(rows):
            for i in range(nx):
                c += 1
                f.write(f"{c} 0 quad {node(i, j)} {node(i + 1, j)} "
                        f"{node(i + 1, j + 1)} {node(i, j + 1)}\n")
        for bid, a, b in lines:
            c += 1
            f.write(f"{c} {bid} line {a} {b}\n")
