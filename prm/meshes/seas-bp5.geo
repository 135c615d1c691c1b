// SEAS BP5-QD (Jiang et al. 2022, JGR 127, e2021JB023519): one side of the
// vertical strike-slip fault in a half-space, for the symmetric reduction
// of prm/seas-bp5-qd.prm (the body y >= 0 against a rigid mirror at y = 0
// with a free normal displacement). Coordinates: x along strike, y the
// distance from the fault, z up (the free surface z = 0). Tags: 1 the
// rate-and-state rectangle |x| <= 50 km, -40 km <= z <= 0 of the fault
// plane (contact); 5 the rest of the fault plane (creeps at the plate
// rate: load); 2 the far side y = Ly, 6 the strike ends x = +-Lx, 3 the
// free surface z = 0 and 4 the bottom z = -Lz (prm/seas-bp5-qd.prm: all
// traction free); volume 10. Coarse hexahedra of h on the rectangle,
// growing by r per cell away from it; Mesh/Local refinements halve them
// toward the fault. Regenerate (in git: h = 4 km, Lx = 400, Ly = Lz = 200
// km; the domain-size study in benchmarks/seas-bp5/README.md):
//   gmsh -3 -format msh2 -o seas-bp5.msh seas-bp5.geo
// Half and double the far field:
//   gmsh -3 -format msh2 -setnumber Lx 200e3 -setnumber Ly 100e3
//        -setnumber Lz 100e3 -o seas-bp5-half.msh seas-bp5.geo
If (!Exists(Lx))
  Lx = 400e3;
EndIf
If (!Exists(Ly))
  Ly = 200e3;
EndIf
If (!Exists(Lz))
  Lz = 200e3;
EndIf
If (!Exists(h))
  h = 4e3;
EndIf
r = 1.3;
X = 50e3; W = 40e3;
// the number of cells of growth r from h that span a length s
n_x = Ceil(Log(1 + (r - 1) * (Lx - X) / h) / Log(r));
n_z = Ceil(Log(1 + (r - 1) * (Lz - W) / h) / Log(r));
n_y = Ceil(Log(1 + (r - 1) * Ly / h) / Log(r));

xs[] = {-Lx, -X, X, Lx};
zs[] = {-Lz, -W, 0};
For i In {0 : 3}
  For j In {0 : 2}
    Point(1 + i + 4 * j) = {xs[i], 0, zs[j]};
  EndFor
EndFor
// along strike (from the rectangle outward for the progressions)
For j In {0 : 2}
  Line(10 + 3 * j) = {2 + 4 * j, 1 + 4 * j};
  Line(11 + 3 * j) = {2 + 4 * j, 3 + 4 * j};
  Line(12 + 3 * j) = {3 + 4 * j, 4 + 4 * j};
  Transfinite Curve{10 + 3 * j, 12 + 3 * j} = n_x + 1 Using Progression r;
  Transfinite Curve{11 + 3 * j} = Round(2 * X / h) + 1;
EndFor
// along depth (downward from z = -W, uniform above)
For i In {0 : 3}
  Line(30 + 2 * i) = {5 + i, 1 + i};
  Line(31 + 2 * i) = {5 + i, 9 + i};
  Transfinite Curve{30 + 2 * i} = n_z + 1 Using Progression r;
  Transfinite Curve{31 + 2 * i} = Round(W / h) + 1;
EndFor
// the six rectangles, counterclockwise in (x, z): strike[i + 3 j] is the
// edge of column i at row line j, forward in x; up[i + 4 j] the edge at
// column line i of row j, upward
For j In {0 : 2}
  strike[3 * j] = -(10 + 3 * j);
  strike[1 + 3 * j] = 11 + 3 * j;
  strike[2 + 3 * j] = 12 + 3 * j;
EndFor
For i In {0 : 3}
  up[i] = -(30 + 2 * i);
  up[i + 4] = 31 + 2 * i;
EndFor
s = 0;
For i In {0 : 2}
  For j In {0 : 1}
    Curve Loop(100 + s) = {strike[i + 3 * j], up[i + 1 + 4 * j],
                           -strike[i + 3 * (j + 1)], -up[i + 4 * j]};
    Plane Surface(100 + s) = {100 + s};
    Transfinite Surface{100 + s};
    Recombine Surface{100 + s};
    s += 1;
  EndFor
EndFor
// layers away from the fault, growing by r from h
sum = 0;
For k In {0 : n_y - 1}
  sum += h * r^k;
  heights[k] = sum;
  ones[k] = 1;
EndFor
For k In {0 : n_y - 1}
  heights[k] = heights[k] / sum;
EndFor
out[] = Extrude {0, Ly, 0} { Surface{100 : 105}; Layers{ones[], heights[]}; Recombine; };
e = 1;
Physical Surface(1) = Surface In BoundingBox{-X - e, -e, -W - e, X + e, e, e};
fault[] = Surface In BoundingBox{-Lx - e, -e, -Lz - e, Lx + e, e, e};
Physical Surface(5) = {fault[]};
Physical Surface(5) -= {Surface In BoundingBox{-X - e, -e, -W - e, X + e, e, e}};
Physical Surface(2) = Surface In BoundingBox{-Lx - e, Ly - e, -Lz - e, Lx + e, Ly + e, e};
Physical Surface(3) = Surface In BoundingBox{-Lx - e, -e, -e, Lx + e, Ly + e, e};
Physical Surface(4) = Surface In BoundingBox{-Lx - e, -e, -Lz - e, Lx + e, Ly + e, -Lz + e};
Physical Surface(6) = {Surface In BoundingBox{-Lx - e, -e, -Lz - e, -Lx + e, Ly + e, e},
                       Surface In BoundingBox{Lx - e, -e, -Lz - e, Lx + e, Ly + e, e}};
Physical Volume(10) = Volume "*";
