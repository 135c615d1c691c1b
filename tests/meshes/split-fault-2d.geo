// SPDX-License-Identifier: LGPL-2.1-or-later
// SEAS BP1's half-space (prm/meshes/seas-bp1.geo) with both sides of the
// fault: the body x >= 0 of seas-bp1.geo and its mirror image x <= 0, the
// fault x = 0 meshed twice (points 1-3 and 101-103 coincide but are not
// merged: split nodes). Tags: the + side as seas-bp1.geo (1 frictional
// fault, 2 creeping fault, 3 surface, 4 bottom, 5 remote side, 10 volume),
// the - side 11 (frictional fault), 12 (creeping fault), 13 (surface),
// 14 (bottom), 15 (remote side x = -L), 20 (volume). For the test
// green_function_split (its header says what it checks).
// Regenerate: gmsh -2 -format msh2 -o split-fault-2d.msh split-fault-2d.geo
If (!Exists(L))
  L = 400e3;
EndIf
W = 40e3;
h = 1.6e3;
r = 1.3;
n_far = Ceil(Log(1 + (r - 1) * (L - W) / h) / Log(r));
n_x = Ceil(Log(1 + (r - 1) * L / h) / Log(r));

For side In {0:1}
  s = 1 - 2 * side; // +1, -1
  o = 100 * side;   // point and curve numbers of the side
  Point(o + 1) = {0, 0, 0};
  Point(o + 2) = {0, -W, 0};
  Point(o + 3) = {0, -L, 0};
  Point(o + 4) = {s * L, -L, 0};
  Point(o + 5) = {s * L, -W, 0};
  Point(o + 6) = {s * L, 0, 0};
  Line(o + 1) = {o + 1, o + 2};
  Line(o + 2) = {o + 2, o + 3};
  Line(o + 3) = {o + 3, o + 4};
  Line(o + 4) = {o + 4, o + 5};
  Line(o + 5) = {o + 5, o + 6};
  Line(o + 6) = {o + 6, o + 1};
  Line(o + 7) = {o + 2, o + 5};
  Transfinite Curve{o + 1, o + 5} = W / h + 1;
  Transfinite Curve{o + 2} = n_far + 1 Using Progression r;
  Transfinite Curve{o + 4} = n_far + 1 Using Progression 1 / r;
  Transfinite Curve{o + 3, o + 7} = n_x + 1 Using Progression r;
  Transfinite Curve{o + 6} = n_x + 1 Using Progression 1 / r;
  Curve Loop(o + 1) = {o + 1, o + 7, o + 5, o + 6};
  Plane Surface(o + 1) = {o + 1};
  Curve Loop(o + 2) = {o + 2, o + 3, o + 4, -(o + 7)};
  Plane Surface(o + 2) = {o + 2};
  Transfinite Surface{o + 1, o + 2};
  Recombine Surface{o + 1, o + 2};
EndFor

Physical Curve(1) = {1};
Physical Curve(2) = {2};
Physical Curve(3) = {6};
Physical Curve(4) = {3};
Physical Curve(5) = {4, 5};
Physical Surface(10) = {1, 2};
Physical Curve(11) = {101};
Physical Curve(12) = {102};
Physical Curve(13) = {106};
Physical Curve(14) = {103};
Physical Curve(15) = {104, 105};
Physical Surface(20) = {101, 102};
