// SPDX-License-Identifier: LGPL-2.1-or-later
// tests/meshes/box-fault-3d.geo with both sides of its fault: the body
// y in [0, 12] km and its mirror image y in [-12, 0] km as two boxes of
// OpenCASCADE that are not fused, so that the fault plane y = 0 is meshed
// once per box (split nodes, coincident). Coarse cells of 2 km. Tags: the
// + side 1 (fault, contact), 2 (y = 12 km, load); the - side 11 (fault,
// fault-opposite), 12 (y = -12 km, load-opposite); both sides 3 (the free
// surface z = 0) and 4 (the other faces, free); volumes 10 (+) and 20 (-).
// For the test green_function_split. Regenerate:
//   gmsh -3 -format msh2 -o box-split-3d.msh box-split-3d.geo
SetFactory("OpenCASCADE");
X = 12e3; H = 12e3; D = 12e3;
Box(1) = {-X, 0, -D, 2 * X, H, D};
Box(2) = {-X, -H, -D, 2 * X, H, D};
curves[] = Curve{:};
For i In {0:#curves[] - 1}
  bb[] = BoundingBox Curve{curves[i]};
  Transfinite Curve{curves[i]} = (bb[3] - bb[0] > X) ? 13 : 7;
EndFor
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
e = 1;
For side In {0:1}
  faces[] = Boundary{Volume{side + 1};};
  fault[] = {}; far[] = {}; top[] = {}; other[] = {};
  For i In {0:#faces[] - 1}
    bb[] = BoundingBox Surface{faces[i]};
    If (bb[4] - bb[1] < e && Fabs(bb[1]) < e)
      fault[] += faces[i];
    ElseIf (bb[4] - bb[1] < e)
      far[] += faces[i];
    ElseIf (bb[5] - bb[2] < e && Fabs(bb[2]) < e)
      top[] += faces[i];
    Else
      other[] += faces[i];
    EndIf
  EndFor
  Physical Surface(1 + 10 * side) = {fault[]};
  Physical Surface(2 + 10 * side) = {far[]};
  all_top[side] = top[0];
  If (side == 0)
    other_plus[] = other[];
  Else
    Physical Surface(4) = {other_plus[], other[]};
  EndIf
EndFor
Physical Surface(3) = {all_top[0], all_top[1]};
Physical Volume(10) = {1};
Physical Volume(20) = {2};
