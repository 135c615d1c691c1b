// SPDX-License-Identifier: LGPL-2.1-or-later
// SEAS BP6 (Lambert et al. 2025): a 2D antiplane whole space cut by a
// vertical fault x = 0, computed as the one side x >= 0 against a rigid
// mirror (prm/seas-bp6-qd-a.prm). y runs along the fault (the benchmark's
// x3): the frictional and fluid-filled part |y| <= W = 20 km carries
// rate-and-state friction (tag 1, contact), the rest of x = 0 does not slip
// (tag 2, load at the .prm's tiny load velocity), the far sides x = L and
// y = +-L truncate the whole space (tag 3, load too: the displacement of
// a whole space vanishes far away). Coarse cells 1.6 km along the fault
// (25 on the frictional part, so that k refinements give 1600 / 2^k m),
// growing by 1.3 per cell away from it.
// Regenerate: gmsh -2 -format msh2 -o seas-bp6.msh seas-bp6.geo
// Other domain sizes (the domain-size check in benchmarks/seas-bp6):
// gmsh -2 -format msh2 -setnumber L 400e3 -o seas-bp6-400km.msh seas-bp6.geo
If (!Exists(L))
  L = 200e3;
EndIf
W = 20e3;   // half-length of the frictional fault
h = 1.6e3;  // coarse cells on the fault
r = 1.3;    // growth away from it
// the number of cells of growth r from h that span a length s
n_far = Ceil(Log(1 + (r - 1) * (L - W) / h) / Log(r));
n_x = Ceil(Log(1 + (r - 1) * L / h) / Log(r));

Point(1) = {0, -W, 0};
Point(2) = {0, W, 0};
Point(3) = {0, L, 0};
Point(4) = {L, L, 0};
Point(5) = {L, W, 0};
Point(6) = {L, -W, 0};
Point(7) = {L, -L, 0};
Point(8) = {0, -L, 0};

Line(1) = {1, 2};   // fault, frictional
Line(2) = {2, 3};   // fault plane above it, locked
Line(3) = {3, 4};   // far side y = L
Line(4) = {4, 5};   // far side x = L, upper
Line(5) = {5, 6};   // far side x = L, middle
Line(6) = {6, 7};   // far side x = L, lower
Line(7) = {7, 8};   // far side y = -L
Line(8) = {8, 1};   // fault plane below, locked
Line(9) = {2, 5};   // y = W through the body
Line(10) = {1, 6};  // y = -W through the body

Transfinite Curve{1, 5} = 2 * W / h + 1;
Transfinite Curve{2, 6} = n_far + 1 Using Progression r;
Transfinite Curve{4, 8} = n_far + 1 Using Progression 1 / r;
Transfinite Curve{3, 9, 10} = n_x + 1 Using Progression r;
Transfinite Curve{7} = n_x + 1 Using Progression 1 / r;

Curve Loop(1) = {1, 9, 5, -10}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -9};  Plane Surface(2) = {2};
Curve Loop(3) = {8, 10, 6, 7};  Plane Surface(3) = {3};
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};

Physical Curve(1) = {1};              // frictional fault: contact
Physical Curve(2) = {2, 8};           // the rest of the fault plane: load
Physical Curve(3) = {3, 4, 5, 6, 7};  // far sides: load
Physical Surface(10) = {1, 2, 3};
