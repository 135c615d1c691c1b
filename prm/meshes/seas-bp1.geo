// SPDX-License-Identifier: LGPL-2.1-or-later
// SEAS BP1 (Erickson et al. 2020), the one-sided (symmetric) half-space of
// prm/seas-bp1-qd.prm in the benchmark's coordinates: x >= 0 the distance
// from the fault, y = -depth. The fault x = 0 carries rate-and-state
// friction down to W_f = 40 km (tag 1, contact) and creeps at the plate
// rate below (tag 2, load); the free surface y = 0 is traction free (tag
// 3). The bottom y = -L (tag 4) and the remote side x = L (tag 5) truncate
// the half-space: BP1-QD makes the bottom traction free and loads the
// remote side at the plate rate (prm/seas-bp1-qd.prm), BP1-FD makes both
// absorbing (prm/seas-bp1-fd.prm). Coarse cells: 1.6 km along the fault (25 on the
// frictional part, so that k refinements give 1600 / 2^k m), growing by
// 1.3 per cell away from it (L = 400 km, about 17 cells).
// Regenerate: gmsh -2 -format msh2 -o seas-bp1.msh seas-bp1.geo
// Other domain sizes (the domain-size check in doc/seas-bp1.md):
// gmsh -2 -format msh2 -setnumber L 200e3 -o seas-bp1-200km.msh seas-bp1.geo
// prm/seas-bp2-qd.prm runs on 800 km (seas-bp1-800km.msh, in git):
// gmsh -2 -format msh2 -setnumber L 800e3 -o seas-bp1-800km.msh seas-bp1.geo
If (!Exists(L))
  L = 400e3;
EndIf
W = 40e3;   // frictional fault
h = 1.6e3;  // coarse cells on the fault
r = 1.3;    // growth away from it
// the number of cells of growth r from h that span a length s
n_far = Ceil(Log(1 + (r - 1) * (L - W) / h) / Log(r));
n_x = Ceil(Log(1 + (r - 1) * L / h) / Log(r));

Point(1) = {0, 0, 0};
Point(2) = {0, -W, 0};
Point(3) = {0, -L, 0};
Point(4) = {L, -L, 0};
Point(5) = {L, -W, 0};
Point(6) = {L, 0, 0};

Line(1) = {1, 2}; // fault, frictional
Line(2) = {2, 3}; // fault, creeping
Line(3) = {3, 4}; // bottom
Line(4) = {4, 5}; // remote side, lower
Line(5) = {5, 6}; // remote side, upper
Line(6) = {6, 1}; // free surface
Line(7) = {2, 5}; // the depth W_f through the body

Transfinite Curve{1, 5} = W / h + 1;
Transfinite Curve{2} = n_far + 1 Using Progression r;
Transfinite Curve{4} = n_far + 1 Using Progression 1 / r;
Transfinite Curve{3, 7} = n_x + 1 Using Progression r;
Transfinite Curve{6} = n_x + 1 Using Progression 1 / r;

Curve Loop(1) = {1, 7, 5, 6};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Curve(1) = {1};          // frictional fault: contact
Physical Curve(2) = {2};          // creeping fault: load
Physical Curve(3) = {6};          // free surface: free
Physical Curve(4) = {3};          // bottom: free (QD), absorbing (FD)
Physical Curve(5) = {4, 5};       // remote side: load (QD), absorbing (FD)
Physical Surface(10) = {1, 2};
