// SPDX-License-Identifier: LGPL-2.1-or-later
// SEAS BP3 (Erickson et al. 2023, BSSA): a half-space with a planar fault
// that dips `dip` degrees (30, 60 or 90) from the surface point (0, 0),
// both sides meshed apart (split nodes: a fault between two deformable
// sides, doc/mesh-file.md), x to the right, y up. The fault's
// rate-and-state part runs W_f = 40 km down dip (1.6 km segments, 800 m
// cells after the subdivision into quadrilaterals, refined by
// rsfcycle toward it: prm/seas-bp3-qd.prm), its creeping extension to the
// bottom at 4000 km depth; the far sides 4000 km beyond. The 2D
// displacement of slip decays only like 1/r, so the truncation of the
// half-space shows in the surface displacement: with 400 km it put the
// jumps at +-8 km of an event 4 - 8 % off HBI's half-space solution, with
// 4000 km within 2 % (benchmarks/seas-bp3/README.md). The hanging wall
// (x > fault) is the + side. Tags:
// 1 the fault 0 - 40 km on the hanging wall (contact), 2 its extension
// (creep), 11 and 12 the same on the footwall (fault-opposite), 3 the free
// surface, 4 the bottom, 5 the hanging wall's far side (load), 15 the
// footwall's (load-opposite); volumes 10 (hanging wall) and 20 (footwall).
// Regenerate (e.g. dip 30):
//   gmsh -2 -format msh2 -setnumber dip 30 -o seas-bp3-30.msh seas-bp3.geo
// Other geometries (-setnumber NAME VALUE): the fault's frictional length
// Wf, the segment size h on it, the depth D and the far sides' distance L
// (prm/subduction-2d-slab.prm: a 15-degree megathrust, frictional to
// 53.6 km depth,
//   gmsh -2 -format msh2 -setnumber dip 15 -setnumber Wf 207055
//        -setnumber h 2588.19 -setnumber D 1000e3 -setnumber L 2000e3
//        -o subduction-2d-slab.msh seas-bp3.geo).
If (!Exists(dip))
  dip = 60;
EndIf
If (!Exists(Wf))
  Wf = 40e3;
EndIf
If (!Exists(h))
  h = 1600;
EndIf
If (!Exists(D))
  D = 4000e3;
EndIf
If (!Exists(L))
  L = 4000e3;
EndIf
psi = dip * Pi / 180;
xf = Wf * Cos(psi); yf = -Wf * Sin(psi); xb = D / Tan(psi);
For side In {0:1}
  o = 100 * side;
  Point(o + 1) = {0, 0, 0, h};
  Point(o + 2) = {xf, yf, 0, h};
  Point(o + 3) = {xb, -D, 0, 400e3};
  Line(o + 1) = {o + 1, o + 2};
  Line(o + 2) = {o + 2, o + 3};
  Transfinite Curve{o + 1} = Wf / h + 1;
  Transfinite Curve{o + 2} = 50 Using Progression 1.15;
EndFor
Point(11) = {xb + L, -D, 0, 800e3}; Point(12) = {xb + L, 0, 0, 800e3};
Point(13) = {2 * Wf, 0, 0, 8e3};
Point(111) = {-L, -D, 0, 800e3}; Point(112) = {-L, 0, 0, 800e3};
Point(113) = {-2 * Wf, 0, 0, 8e3};
Line(11) = {3, 11}; Line(12) = {11, 12}; Line(13) = {12, 13};
Line(14) = {13, 1};
Line(111) = {103, 111}; Line(112) = {111, 112}; Line(113) = {112, 113};
Line(114) = {113, 101};
Curve Loop(1) = {1, 2, 11, 12, 13, 14}; Plane Surface(1) = {1};
Curve Loop(2) = {101, 102, 111, 112, 113, 114}; Plane Surface(2) = {2};
Recombine Surface{1, 2};
Mesh.RecombinationAlgorithm = 1; Mesh.SubdivisionAlgorithm = 1;
Physical Curve(1) = {1}; Physical Curve(2) = {2};
Physical Curve(11) = {101}; Physical Curve(12) = {102};
Physical Curve(3) = {13, 14, 113, 114};
Physical Curve(4) = {11, 111};
Physical Curve(5) = {12};
Physical Curve(15) = {112};
Physical Surface(10) = {1}; Physical Surface(20) = {2};
