// A square glass (a tumbler) standing on a table: the grid is the air
// around and inside it. Its four walls and its base are holes of real
// thickness in the grid, so that their inner and outer faces are grid
// boundaries. The box is cut into 5 x 5 x 3 blocks along the glass's
// faces; every air block is a structured (transfinite) hexahedral block
// of cells of side at most h, so the grid is Cartesian.
//
//   gmsh -3 -format msh41 -setnumber h 0.005 glass_3d.geo -o glass_3d.msh
//
// Boundary ids (physical surfaces): 1 the sides of the air box, 3 the
// table (z = 0 outside the glass), 4 the top, 5 the glass (every face of
// it). The air is physical volume 1.
DefineConstant[ h = 0.005 ];   // cell size [m]
DefineConstant[ W = 0.16 ];    // width and depth of the air box [m]
DefineConstant[ H = 0.16 ];    // height of the air box [m]
DefineConstant[ Ri = 0.0325 ]; // inner half-width of the glass [m]
DefineConstant[ t = 0.005 ];   // wall thickness [m]
DefineConstant[ tb = 0.005 ];  // base thickness [m]
DefineConstant[ Hg = 0.1 ];    // height of the glass [m]

c = W / 2;
xs[] = {0, c - Ri - t, c - Ri, c + Ri, c + Ri + t, W}; // x and y
zs[] = {0, tb, Hg, H};

// Entity numbers: point (i, k, j) at (xs[i], xs[k], zs[j]) is
// 1 + 100 i + 10 k + j; edges along x, y, z from that point 10000 +,
// 20000 +, 30000 + the point's number; faces normal to x, y, z at that
// point 40000 +, 50000 +, 60000 +; block (i, k, j) 70000 + its corner's.
For i In {0:5}
  For k In {0:5}
    For j In {0:3}
      Point(1 + 100 * i + 10 * k + j) = {xs[i], xs[k], zs[j]};
    EndFor
  EndFor
EndFor
For i In {0:5}
  For k In {0:5}
    For j In {0:3}
      p = 1 + 100 * i + 10 * k + j;
      If (i < 5)
        Line(10000 + p) = {p, p + 100};
        Transfinite Curve{10000 + p} = Ceil((xs[i + 1] - xs[i]) / h - 1e-6) + 1;
      EndIf
      If (k < 5)
        Line(20000 + p) = {p, p + 10};
        Transfinite Curve{20000 + p} = Ceil((xs[k + 1] - xs[k]) / h - 1e-6) + 1;
      EndIf
      If (j < 3)
        Line(30000 + p) = {p, p + 1};
        Transfinite Curve{30000 + p} = Ceil((zs[j + 1] - zs[j]) / h - 1e-6) + 1;
      EndIf
    EndFor
  EndFor
EndFor

// The kind of block (bi, bk, bj), bi and bk from -1 to 5, bj from -1 to
// 3: 0 outside the box, 1 air, 2 glass, at
// kinds[(bi + 1) * 35 + (bk + 1) * 5 + bj + 1]. The glass: the ring of
// walls (bi, bk in 1..3 but not both 2) up to Hg, and the base (2, 2)
// under tb.
kinds[] = {};
For bi In {-1:5}
  For bk In {-1:5}
    For bj In {-1:3}
      kind = 0;
      If (bi >= 0 && bi <= 4 && bk >= 0 && bk <= 4 && bj >= 0 && bj <= 2)
        kind = 1;
        If (bi >= 1 && bi <= 3 && bk >= 1 && bk <= 3 && bj <= 1)
          If (bi != 2 || bk != 2 || bj == 0)
            kind = 2;
          EndIf
        EndIf
      EndIf
      kinds[] += {kind};
    EndFor
  EndFor
EndFor

air[] = {};
sides[] = {};
table[] = {};
top[] = {};
glass[] = {};
// faces, each between two blocks (one of them possibly outside)
For i In {0:5}
  For k In {0:5}
    For j In {0:3}
      p = 1 + 100 * i + 10 * k + j;
      For dir In {0:2}
        made = 0;
        If (dir == 0 && k < 5 && j < 3)
          Curve Loop(40000 + p) = {20000 + p, 30000 + p + 10, -(20000 + p + 1), -(30000 + p)};
          s = 40000 + p;
          a = kinds[i * 35 + (k + 1) * 5 + j + 1];
          b = kinds[(i + 1) * 35 + (k + 1) * 5 + j + 1];
          made = 1;
        EndIf
        If (dir == 1 && i < 5 && j < 3)
          Curve Loop(50000 + p) = {10000 + p, 30000 + p + 100, -(10000 + p + 1), -(30000 + p)};
          s = 50000 + p;
          a = kinds[(i + 1) * 35 + k * 5 + j + 1];
          b = kinds[(i + 1) * 35 + (k + 1) * 5 + j + 1];
          made = 1;
        EndIf
        If (dir == 2 && i < 5 && k < 5)
          Curve Loop(60000 + p) = {10000 + p, 20000 + p + 100, -(10000 + p + 10), -(20000 + p)};
          s = 60000 + p;
          a = kinds[(i + 1) * 35 + (k + 1) * 5 + j];
          b = kinds[(i + 1) * 35 + (k + 1) * 5 + j + 1];
          made = 1;
        EndIf
        // a face that touches air
        If (made == 1 && (a == 1 || b == 1))
          Plane Surface(s) = {s};
          Transfinite Surface{s};
          Recombine Surface{s};
          If (a != 1 || b != 1)
            other = a + b - 1; // the kind on the other side
            If (other == 2)
              glass[] += {s};
            ElseIf (dir == 2 && j == 0)
              table[] += {s};
            ElseIf (dir == 2)
              top[] += {s};
            Else
              sides[] += {s};
            EndIf
          EndIf
        EndIf
      EndFor
    EndFor
  EndFor
EndFor
// the air blocks
For i In {0:4}
  For k In {0:4}
    For j In {0:2}
      If (kinds[(i + 1) * 35 + (k + 1) * 5 + j + 1] == 1)
        p = 1 + 100 * i + 10 * k + j;
        Surface Loop(70000 + p) = {40000 + p, 40000 + p + 100, 50000 + p,
                                   50000 + p + 10, 60000 + p, 60000 + p + 1};
        Volume(70000 + p) = {70000 + p};
        Transfinite Volume{70000 + p};
        Recombine Volume{70000 + p};
        air[] += {70000 + p};
      EndIf
    EndFor
  EndFor
EndFor

Physical Volume(1) = {air[]};
Physical Surface(1) = {sides[]};
Physical Surface(3) = {table[]};
Physical Surface(4) = {top[]};
Physical Surface(5) = {glass[]};
