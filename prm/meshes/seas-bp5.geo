// SPDX-License-Identifier: LGPL-2.1-or-later
// SEAS BP5-QD and BP4-QD (Jiang et al. 2022, JGR 127, e2021JB023519) and
// BP7-QD: one side of a vertical strike-slip fault, for the antisymmetric
// reduction of prm/seas-bp5-qd.prm, prm/seas-bp4-qd.prm and
// prm/seas-bp7-qd.prm (the body y >= 0 against a
// rigid mirror at y = 0 with a free normal displacement). Coordinates: x
// along strike, y the distance from the fault, z up. BP5 (whole = 0, the
// default): a half-space below the free surface z = 0, the rate-and-state
// rectangle |x| <= 50 km, -40 km <= z <= 0; BP4 (whole = 1): a whole space
// truncated at z = +-Lz, the rectangle |x| <= 50 km, |z| <= 40 km. Tags: 1
// the rectangle (contact); 5 the rest of the fault plane (creep: slides at
// the plate rate); 2 the far side y = Ly (free slip); 6 the strike ends x =
// +-Lx, 3 the top (BP5: the free surface) and 4 the bottom z = -Lz
// (traction free); volume 10. Coarse hexahedra of h on the rectangle,
// growing by r per cell away from it; Mesh/Local refinements halve them
// toward the fault. Regenerate (in git: h = 4 km, Lx = 400, Ly = Lz = 200
// km; the domain-size study in benchmarks/seas-bp5/README.md):
//   gmsh -3 -format msh2 -o seas-bp5.msh seas-bp5.geo
//   gmsh -3 -format msh2 -setnumber whole 1 -o seas-bp4.msh seas-bp5.geo
//   (seas-bp4.msh, 3 MB, is not in git: quickstart.sh makes it)
//   gmsh -3 -format msh2 -setnumber whole 1 -setnumber X 400
//        -setnumber W 400 -setnumber h 80 -setnumber Lx 3200
//        -setnumber Ly 1600 -setnumber Lz 3200 -o seas-bp7.msh seas-bp5.geo
// (BP7: the 800 x 800 m square in a whole space of 6.4 x 1.6 x 6.4 km)
// Double the far field:
//   gmsh -3 -format msh2 -setnumber Lx 800e3 -setnumber Ly 400e3
//        -setnumber Lz 400e3 -o seas-bp5-double.msh seas-bp5.geo
If (!Exists(whole))
  whole = 0;
EndIf
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
// the rectangle's half length X and its depth (BP4, BP7: half height) W
If (!Exists(X))
  X = 50e3;
EndIf
If (!Exists(W))
  W = 40e3;
EndIf
r = 1.3;
// the number of cells of growth r from h that span a length s
n_x = Ceil(Log(1 + (r - 1) * (Lx - X) / h) / Log(r));
n_z = Ceil(Log(1 + (r - 1) * (Lz - W) / h) / Log(r));
n_y = Ceil(Log(1 + (r - 1) * Ly / h) / Log(r));

xs[] = {-Lx, -X, X, Lx};
If (whole)
  zs[] = {-Lz, -W, W, Lz};
Else
  zs[] = {-Lz, -W, 0};
EndIf
nz = #zs[];
For i In {0 : 3}
  For j In {0 : nz - 1}
    Point(1 + i + 4 * j) = {xs[i], 0, zs[j]};
  EndFor
EndFor
// along strike (from the rectangle outward for the progressions)
For j In {0 : nz - 1}
  Line(10 + 3 * j) = {2 + 4 * j, 1 + 4 * j};
  Line(11 + 3 * j) = {2 + 4 * j, 3 + 4 * j};
  Line(12 + 3 * j) = {3 + 4 * j, 4 + 4 * j};
  Transfinite Curve{10 + 3 * j, 12 + 3 * j} = n_x + 1 Using Progression r;
  Transfinite Curve{11 + 3 * j} = Round(2 * X / h) + 1;
EndFor
// along z: downward from z = -W, uniform on the rectangle, upward from
// z = W (whole space); up[i + 4 j] is the edge at column line i of row j,
// upward
For i In {0 : 3}
  Line(30 + 3 * i) = {5 + i, 1 + i};
  Transfinite Curve{30 + 3 * i} = n_z + 1 Using Progression r;
  up[i] = -(30 + 3 * i);
  Line(31 + 3 * i) = {5 + i, 9 + i};
  Transfinite Curve{31 + 3 * i} = Round((zs[2] + W) / h) + 1;
  up[i + 4] = 31 + 3 * i;
  If (whole)
    Line(32 + 3 * i) = {9 + i, 13 + i};
    Transfinite Curve{32 + 3 * i} = n_z + 1 Using Progression r;
    up[i + 8] = 32 + 3 * i;
  EndIf
EndFor
// the rectangles, counterclockwise in (x, z): strike[i + 3 j] is the edge
// of column i at row line j, forward in x
For j In {0 : nz - 1}
  strike[3 * j] = -(10 + 3 * j);
  strike[1 + 3 * j] = 11 + 3 * j;
  strike[2 + 3 * j] = 12 + 3 * j;
EndFor
s = 0;
For i In {0 : 2}
  For j In {0 : nz - 2}
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
out[] = Extrude {0, Ly, 0} { Surface{100 : 100 + s - 1}; Layers{ones[], heights[]}; Recombine; };
e = 1;
top = zs[nz - 1];
Physical Surface(1) = Surface In BoundingBox{-X - e, -e, -W - e, X + e, e, zs[2] + e};
fault[] = Surface In BoundingBox{-Lx - e, -e, -Lz - e, Lx + e, e, top + e};
Physical Surface(5) = {fault[]};
Physical Surface(5) -= {Surface In BoundingBox{-X - e, -e, -W - e, X + e, e, zs[2] + e}};
Physical Surface(2) = Surface In BoundingBox{-Lx - e, Ly - e, -Lz - e, Lx + e, Ly + e, top + e};
Physical Surface(3) = Surface In BoundingBox{-Lx - e, -e, top - e, Lx + e, Ly + e, top + e};
Physical Surface(4) = Surface In BoundingBox{-Lx - e, -e, -Lz - e, Lx + e, Ly + e, -Lz + e};
Physical Surface(6) = {Surface In BoundingBox{-Lx - e, -e, -Lz - e, -Lx + e, Ly + e, top + e},
                       Surface In BoundingBox{Lx - e, -e, -Lz - e, Lx + e, Ly + e, top + e}};
Physical Volume(10) = Volume "*";
