// SPDX-License-Identifier: LGPL-2.1-or-later
// The coarse mesh of the built-in 2D wedge (GridGenerator::simplex of the
// triangle A, B, C: three quadrilaterals through the edge midpoints and the
// centroid) in the paper's coordinates (trench A at the origin, x toward
// the backstop, y up) with one volume tag, for the test mesh_file_simplex:
// Scene = mesh-file on this mesh must reproduce the built-in wedge.
// Regenerate: gmsh -2 -format msh2 -o wedge-simplex-2d.msh wedge-simplex-2d.geo
Point(1) = {0, 0, 0};             // A (trench)
Point(2) = {1, -0.27, 0};         // B (base at the backstop)
Point(3) = {1, 0, 0};             // C (top of the backstop)
Point(4) = {0.5, -0.135, 0};      // midpoint of A-B
Point(5) = {1, -0.135, 0};        // midpoint of B-C
Point(6) = {0.5, 0, 0};           // midpoint of C-A
Point(7) = {2 / 3, -0.09, 0};     // centroid

Line(1) = {1, 4}; Line(2) = {4, 2};   // base
Line(3) = {2, 5}; Line(4) = {5, 3};   // backstop
Line(5) = {3, 6}; Line(6) = {6, 1};   // surface
Line(7) = {4, 7}; Line(8) = {5, 7}; Line(9) = {6, 7};

Curve Loop(1) = {1, 7, -9, 6};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 8, -7};  Plane Surface(2) = {2};
Curve Loop(3) = {-8, 4, 5, 9};  Plane Surface(3) = {3};
Transfinite Curve{1:9} = 2;
Transfinite Surface{1:3};
Recombine Surface{1:3};

Physical Curve(1) = {1, 2};       // contact
Physical Curve(2) = {3, 4};       // load
Physical Curve(3) = {5, 6};       // free
Physical Surface(10) = {1, 2, 3};
