// SPDX-License-Identifier: LGPL-2.1-or-later
// A hexahedral box against a vertical fault, for the 3D tests of the
// Green's-function method (green_function_3d): the fault plane y = 0
// (tag 1, contact), x along strike in [-12, 12] km, z up in [-12, 0] km;
// the body y in [0, 12] km; the far side y = 12 km (tag 2, load), the free
// surface z = 0 (tag 3, free), the other faces (tag 4, free); volume 10.
// Coarse cells of 2 km. Regenerate:
//   gmsh -3 -format msh2 -o box-fault-3d.msh box-fault-3d.geo
X = 12e3; H = 12e3; D = 12e3;
Point(1) = {-X, 0, -D};
Point(2) = {X, 0, -D};
Line(1) = {1, 2};
Transfinite Curve{1} = 13;
base[] = Extrude {0, 0, D} { Curve{1}; Layers{6}; Recombine; };
body[] = Extrude {0, H, 0} { Surface{base[1]}; Layers{6}; Recombine; };
e = 1;
Physical Surface(1) = Surface In BoundingBox{-X - e, -e, -D - e, X + e, e, e};
Physical Surface(2) = Surface In BoundingBox{-X - e, H - e, -D - e, X + e, H + e, e};
Physical Surface(3) = Surface In BoundingBox{-X - e, -e, -e, X + e, H + e, e};
Physical Surface(4) = {Surface In BoundingBox{-X - e, -e, -D - e, -X + e, H + e, e},
                       Surface In BoundingBox{X - e, -e, -D - e, X + e, H + e, e},
                       Surface In BoundingBox{-X - e, -e, -D - e, X + e, H + e, -D + e}};
Physical Volume(10) = {body[1]};
