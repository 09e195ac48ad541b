// A glass standing on a table, in section (2D): the grid is the air
// around and inside it. The glass's walls and base are holes of real
// thickness in the grid, so that its inner and outer faces are grid
// boundaries. Every block is a structured (transfinite) rectangle of
// square-ish cells of side h, so the grid is Cartesian.
//
//   gmsh -2 -format msh41 -setnumber h 0.0025 glass_2d.geo -o glass_2d.msh
//
// Boundary ids (physical curves): 1 the sides of the air box, 3 the
// table (y = 0 outside the glass), 4 the top, 5 the glass (every face of
// it). The air is physical surface 1.
DefineConstant[ h = 0.0025 ];  // cell size [m]
DefineConstant[ W = 0.16 ];    // width of the air box [m]
DefineConstant[ H = 0.16 ];    // height of the air box [m]
DefineConstant[ Ri = 0.0325 ]; // inner half-width of the glass [m]
DefineConstant[ t = 0.0025 ];  // wall thickness [m]
DefineConstant[ tb = 0.005 ];  // base thickness [m]
DefineConstant[ Hg = 0.1 ];    // height of the glass [m]

cx = W / 2;
xs[] = {0, cx - Ri - t, cx - Ri, cx + Ri, cx + Ri + t, W};
ys[] = {0, tb, Hg, H};

// points (i, j) at (xs[i], ys[j])
For i In {0:5}
  For j In {0:3}
    Point(100 * i + j + 1) = {xs[i], ys[j], 0};
  EndFor
EndFor
// horizontal edges (i, j) - (i+1, j), vertical edges (i, j) - (i, j+1),
// with as many cells as make them at most h long
For i In {0:4}
  For j In {0:3}
    Line(1000 + 10 * i + j) = {100 * i + j + 1, 100 * (i + 1) + j + 1};
    Transfinite Curve{1000 + 10 * i + j} = Ceil((xs[i + 1] - xs[i]) / h - 1e-6) + 1;
  EndFor
EndFor
For i In {0:5}
  For j In {0:2}
    Line(2000 + 10 * i + j) = {100 * i + j + 1, 100 * i + j + 2};
    Transfinite Curve{2000 + 10 * i + j} = Ceil((ys[j + 1] - ys[j]) / h - 1e-6) + 1;
  EndFor
EndFor

// blocks (i, j) = 10 i + j; the glass: the walls up to Hg, the base
glass[] = {10, 11, 20, 30, 31};
air[] = {};
For i In {0:4}
  For j In {0:2}
    b = 10 * i + j;
    solid = 0;
    For k In {0:#glass[] - 1}
      If (glass[k] == b)
        solid = 1;
      EndIf
    EndFor
    If (solid == 0)
      Curve Loop(3000 + b) = {1000 + 10 * i + j, 2000 + 10 * (i + 1) + j,
                              -(1000 + 10 * i + j + 1), -(2000 + 10 * i + j)};
      Plane Surface(3000 + b) = {3000 + b};
      Transfinite Surface{3000 + b};
      Recombine Surface{3000 + b};
      air[] += {3000 + b};
    EndIf
  EndFor
EndFor

Physical Surface(1) = {air[]};
Physical Curve(1) = {2000, 2001, 2002, 2050, 2051, 2052}; // x = 0, W
Physical Curve(3) = {1000, 1040};                       // the table
Physical Curve(4) = {1003, 1013, 1023, 1033, 1043};     // y = H
Physical Curve(5) = {2010, 2011, 1012, 2021, 1021,      // the glass
                     2031, 1032, 2040, 2041};
