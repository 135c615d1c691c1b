// SPDX-License-Identifier: LGPL-2.1-or-later
// A kilometre-scale subduction zone for Scene = mesh-file
// (prm/subduction-2d.prm): the upper plate as a 200 km wedge over a
// megathrust dipping 15 degrees, in metres, trench at the origin, x
// landward, y up.
//   T = (0, 0) trench, S = (200 km, 0) surface at the landward end,
//   B = (200 km, -200 km tan 15 deg = -53.59 km) megathrust at depth
//   megathrust T-B (contact), surface T-S (free), landward side S-B (load:
//   the upper plate is pushed toward the trench, parallel to the
//   megathrust, at the plate rate).
// The megathrust is divided at 10 and 40 km depth (the rate-weakening
// zone), so that coarse vertices lie at the ends of the zone.
// Regenerate (gmsh 4, Debian 12):
//   gmsh -2 -format msh2 -o subduction-2d.msh subduction-2d.geo
L = 200e3;
dip = 15 * Pi / 180;
h = 30e3;                           // coarse triangle size (before subdivision)

Point(1) = {0, 0, 0, h};                           // T
Point(2) = {10e3 / Tan(dip), -10e3, 0, h};         // 10 km depth
Point(3) = {40e3 / Tan(dip), -40e3, 0, h};         // 40 km depth
Point(4) = {L, -L * Tan(dip), 0, h};               // B
Point(5) = {L, 0, 0, h};                           // S

Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};   // megathrust
Line(4) = {4, 5};                                       // landward side
Line(5) = {5, 1};                                       // surface
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Mesh.Algorithm = 6;            // Frontal-Delaunay triangles ...
Mesh.SubdivisionAlgorithm = 1; // ... each split into three quadrilaterals

Physical Curve(1) = {1, 2, 3};     // contact (megathrust)
Physical Curve(2) = {4};           // load
Physical Curve(3) = {5};           // free
Physical Surface(10) = {1};        // upper plate
