// SPDX-License-Identifier: LGPL-2.1-or-later
// A fault through a whole plane, one side modelled: the body x >= 0 against
// the fault x = 0, which spans y in [-L, L] whole (tag 1, contact); the
// other sides (tag 2) truncate the plane at L = 400 km. Coarse cells of
// 1.6 km along the fault for |y| < W = 40 km, growing by 1.3 per cell away
// from it (as prm/meshes/seas-bp1.geo, mirrored about y = 0). For the test
// green_operator_normal (the operator against the closed forms of a held
// and a free normal displacement). Regenerate:
//   gmsh -2 -format msh2 -o whole-fault-2d.msh whole-fault-2d.geo
L = 400e3; W = 40e3; h = 1.6e3; r = 1.3;
n_far = Ceil(Log(1 + (r - 1) * (L - W) / h) / Log(r));
n_x = Ceil(Log(1 + (r - 1) * L / h) / Log(r));
Point(1) = {0, W, 0};  Point(2) = {0, -W, 0}; Point(3) = {0, -L, 0};
Point(4) = {L, -L, 0}; Point(5) = {L, -W, 0}; Point(6) = {L, W, 0};
Point(7) = {L, L, 0};  Point(8) = {0, L, 0};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 5};
Line(5) = {5, 6};  Line(6) = {6, 7};  Line(7) = {7, 8};  Line(8) = {8, 1};
Line(9) = {2, 5};  Line(10) = {1, 6};
Transfinite Curve{1, 5} = 2 * W / h + 1;
Transfinite Curve{2, 6} = n_far + 1 Using Progression r;
Transfinite Curve{4, 8} = n_far + 1 Using Progression 1 / r;
Transfinite Curve{3, 9, 10} = n_x + 1 Using Progression r;
Transfinite Curve{7} = n_x + 1 Using Progression 1 / r;
Curve Loop(1) = {1, 9, 5, -10};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -9};   Plane Surface(2) = {2};
Curve Loop(3) = {10, 6, 7, 8};   Plane Surface(3) = {3};
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};
Physical Curve(1) = {1, 2, 8};
Physical Curve(2) = {3, 4, 5, 6, 7};
Physical Surface(10) = {1, 2, 3};
