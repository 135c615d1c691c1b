// SPDX-License-Identifier: LGPL-2.1-or-later
// A fault dipping 60 degrees through a half-plane (SEAS BP3's geometry,
// coarse), both sides meshed apart with unstructured quadrilaterals, so
// that their cells differ and only the fault's nodes coincide (split
// nodes): the fault from (0, 0) down dip to the depth 40 km (tag 1 on the
// hanging wall x > fault, 11 on the footwall), its extension to the
// bottom at 200 km (tags 2 and 12); the free surface (3), the bottom (4),
// the far sides (5 hanging wall, 15 footwall); volumes 10 and 20. For
// scripts/green_function_ranks (the refinement toward the patch matched
// on both sides, physics::refine_fault_sides_alike). Regenerate:
//   gmsh -2 -format msh2 -o dipping-split-2d.msh dipping-split-2d.geo
psi = 60 * Pi / 180; Wf = 40e3; D = 200e3; L = 300e3; h = 2e3;
xf = Wf / Tan(psi); xb = D / Tan(psi);
For side In {0:1}
  o = 100 * side;
  Point(o + 1) = {0, 0, 0, h};
  Point(o + 2) = {xf, -Wf, 0, h};
  Point(o + 3) = {xb, -D, 0, 20e3};
  Line(o + 1) = {o + 1, o + 2};
  Line(o + 2) = {o + 2, o + 3};
  Transfinite Curve{o + 1} = 24;
  Transfinite Curve{o + 2} = 30 Using Progression 1.1;
EndFor
// hanging wall (x > fault): side 0; footwall (x < fault): side 1
Point(11) = {xb + L, -D, 0, 40e3}; Point(12) = {xb + L, 0, 0, 40e3};
Point(111) = {-L, -D, 0, 40e3}; Point(112) = {-L, 0, 0, 40e3};
Line(11) = {3, 11}; Line(12) = {11, 12}; Line(13) = {12, 1};
Line(111) = {103, 111}; Line(112) = {111, 112}; Line(113) = {112, 101};
Curve Loop(1) = {1, 2, 11, 12, 13}; Plane Surface(1) = {1};
Curve Loop(2) = {101, 102, 111, 112, 113}; Plane Surface(2) = {2};
Recombine Surface{1, 2};
Mesh.RecombinationAlgorithm = 1; Mesh.SubdivisionAlgorithm = 1;
Physical Curve(1) = {1}; Physical Curve(2) = {2};
Physical Curve(11) = {101}; Physical Curve(12) = {102};
Physical Curve(3) = {13, 113};     // surface
Physical Curve(4) = {11, 111};     // bottom
Physical Curve(5) = {12};          // hanging wall far side
Physical Curve(15) = {112};        // footwall far side
Physical Surface(10) = {1}; Physical Surface(20) = {2};
