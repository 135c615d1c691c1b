// SPDX-License-Identifier: LGPL-2.1-or-later
// A quadrilateral mesh whose contact (tag 1) bends at x = 0.5 (a kinked
// fault), for the test scripts/bad_input: Scene = mesh-file must refuse a
// contact that is not planar. Regenerate:
//   gmsh -2 -format msh2 -o bent-2d.msh bent-2d.geo
Point(1) = {0, 0, 0}; Point(2) = {0.5, -0.1, 0}; Point(3) = {1, -0.3, 0};
Point(4) = {1, 0.5, 0}; Point(5) = {0, 0.5, 0}; Point(6) = {0.5, 0.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 6};
Line(5) = {6, 5}; Line(6) = {5, 1}; Line(7) = {2, 6};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Transfinite Curve{1:7} = 2; Transfinite Surface{1, 2}; Recombine Surface{1, 2};
Physical Curve(1) = {1, 2}; Physical Curve(2) = {3}; Physical Curve(3) = {4, 5, 6};
Physical Surface(10) = {1, 2};
