// SPDX-License-Identifier: LGPL-2.1-or-later
// A hexahedral box against a vertical fault plane whose lower part creeps,
// for the test creep_boundary_3d (SEAS BP5's set-up in small): the fault
// plane y = 0 split into the frictional contact z in [-8, 0] km (tag 1) and
// the creeping part z in [-12, -8] km (tag 5); x along strike in
// [-12, 12] km, z up; the body y in [0, 12] km; the far side y = 12 km
// (tag 2), the free surface z = 0 (tag 3), the strike ends and the bottom
// (tag 4); volume 10. Coarse cells of 2 km. Regenerate:
//   gmsh -3 -format msh2 -o box-creep-3d.msh box-creep-3d.geo
X = 12e3; H = 12e3; D = 12e3; C = 8e3;
Point(1) = {-X, 0, -D};
Point(2) = {X, 0, -D};
Line(1) = {1, 2};
Transfinite Curve{1} = 13;
lower[] = Extrude {0, 0, D - C} { Curve{1}; Layers{2}; Recombine; };
upper[] = Extrude {0, 0, C} { Curve{lower[0]}; Layers{4}; Recombine; };
body1[] = Extrude {0, H, 0} { Surface{lower[1]}; Layers{6}; Recombine; };
body2[] = Extrude {0, H, 0} { Surface{upper[1]}; Layers{6}; Recombine; };
Coherence;
e = 1;
Physical Surface(1) = Surface In BoundingBox{-X - e, -e, -C - e, X + e, e, e};
Physical Surface(5) = Surface In BoundingBox{-X - e, -e, -D - e, X + e, e, -C + e};
Physical Surface(2) = Surface In BoundingBox{-X - e, H - e, -D - e, X + e, H + e, e};
Physical Surface(3) = Surface In BoundingBox{-X - e, -e, -e, X + e, H + e, e};
Physical Surface(4) = {Surface In BoundingBox{-X - e, -e, -D - e, -X + e, H + e, e},
                       Surface In BoundingBox{X - e, -e, -D - e, X + e, H + e, e},
                       Surface In BoundingBox{-X - e, -e, -D - e, X + e, H + e, -D + e}};
Physical Volume(10) = {body1[1], body2[1]};
