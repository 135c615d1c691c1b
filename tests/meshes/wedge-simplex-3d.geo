// SPDX-License-Identifier: LGPL-2.1-or-later
// The coarse mesh of the built-in 3D wedge (the 2D simplex of
// wedge-simplex-2d.geo extruded by 0.6 m in z, one layer of hexahedra) in
// the paper's coordinates, one volume tag, for the test
// mesh_file_simplex_3d: Scene = mesh-file on this mesh must reproduce the
// built-in 3D wedge. Regenerate:
//   gmsh -3 -format msh2 -o wedge-simplex-3d.msh wedge-simplex-3d.geo
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

out[] = Extrude {0, 0, 0.6} { Surface{1, 2, 3}; Layers{1}; Recombine; };
// out[]: for each surface its top, volume and lateral faces (one per edge,
// in the order of its curve loop)
Physical Surface(1) = {out[2], out[8]};            // contact: lines 1, 2
Physical Surface(2) = {out[9], out[15]};           // load: lines 3, 4
Physical Surface(3) = {out[16], out[5]};           // free: lines 5, 6
Physical Surface(4) = {1, 2, 3, out[0], out[6], out[12]}; // free-slip: z = 0, 0.6
Physical Volume(10) = {out[1], out[7], out[13]};
