// SPDX-License-Identifier: LGPL-2.1-or-later
// The laboratory wedge of the paper (doc/model.md §5) as a gmsh geometry, for
// Scene = mesh-file (prm/wedge-2d-mesh.prm). Coordinates as in the paper:
// trench at the origin, x toward the backstop, y up [m].
//   A = (0, 0) trench, C = (1, 0) top of the backstop, B = (1, -0.27)
//   base A-B (contact), surface A-C (free), backstop C-B (load).
// The lower region (the part less than 0.06 m above B) is its own volume
// tag. The base is divided at its midpoint M, as the built-in wedge's
// coarse mesh (GridGenerator::simplex) is, so that at the same number of
// refinements the cells on the patch have the same length.
//
// Regenerate (gmsh 4, Debian 12):
//   gmsh -2 -format msh2 -o wedge-2d.msh wedge-2d.geo
length = 1.0;
depth = 0.27;
lower = 0.06;            // Lower region thickness
h = 0.3;                 // coarse triangle size (before subdivision)

Point(1) = {0, 0, 0, h};                              // A
Point(2) = {length / 2, -depth / 2, 0, h};            // M, midpoint of A-B
yl = -(depth - lower);
Point(3) = {length * (-yl) / depth, yl, 0, h};        // P: base at the lower line
Point(4) = {length, -depth, 0, h};                    // B
Point(5) = {length, yl, 0, h};                        // Q: backstop at the lower line
Point(6) = {length, 0, 0, h};                         // C

Line(1) = {1, 2};   // base A-M
Line(2) = {2, 3};   // base M-P
Line(3) = {3, 4};   // base P-B
Line(4) = {4, 5};   // backstop B-Q
Line(5) = {5, 6};   // backstop Q-C
Line(6) = {6, 1};   // surface C-A
Line(7) = {3, 5};   // lower line P-Q

Curve Loop(1) = {1, 2, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {3, 4, -7};
Plane Surface(2) = {2};

// 2 triangle edges on A-M become 4 quad edges of length |AM|/4 = 0.129 m
Transfinite Curve{1} = 3;
Mesh.CharacteristicLengthMax = h;
Mesh.Algorithm = 6;            // Frontal-Delaunay triangles ...
Mesh.SubdivisionAlgorithm = 1; // ... each split into three quadrilaterals

Physical Curve(1) = {1, 2, 3};     // contact
Physical Curve(2) = {4, 5};        // load (backstop)
Physical Curve(3) = {6};           // free (surface)
Physical Surface(10) = {1};        // upper region
Physical Surface(11) = {2};        // lower region
