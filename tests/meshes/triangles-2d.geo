// SPDX-License-Identifier: LGPL-2.1-or-later
// A triangle mesh of the unit square (tags as the wedge's: 1 contact,
// 2 load, 3 free, volume 10), for the test scripts/bad_input: Scene =
// mesh-file must refuse cells that are not quadrilaterals.
// Regenerate: gmsh -2 -format msh2 -o triangles-2d.msh triangles-2d.geo
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Mesh.CharacteristicLengthMax = 0.5;
Physical Curve(1) = {1}; Physical Curve(2) = {2}; Physical Curve(3) = {3, 4};
Physical Surface(10) = {1};
