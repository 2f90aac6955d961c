// cube.geo: the tiny mesh of tests/unit/test_fcs_gmsh_reader.f90 (see make_data.sh).
// A 2 x 1 x 1 box, 2 x 2 x 1 structured hexahedra (18 nodes, 4 elements).
// groups = 0: no physical groups (save with -save_all); volume_group = 0: surfaces only.
If (!Exists(groups))
  groups = 1;
EndIf
If (!Exists(volume_group))
  volume_group = 1;
EndIf

Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {0, 0, 1};
Point(6) = {2, 0, 1};
Point(7) = {2, 1, 1};
Point(8) = {0, 1, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {1, 4};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {8, 7};
Line(8) = {5, 8};
Line(9) = {1, 5};
Line(10) = {2, 6};
Line(11) = {3, 7};
Line(12) = {4, 8};
Curve Loop(1) = {1, 2, -3, -4};      // z = 0
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -7, -8};      // z = 1
Plane Surface(2) = {2};
Curve Loop(3) = {4, 12, -8, -9};     // x = 0
Plane Surface(3) = {3};
Curve Loop(4) = {2, 11, -6, -10};    // x = 2
Plane Surface(4) = {4};
Curve Loop(5) = {1, 10, -5, -9};     // y = 0
Plane Surface(5) = {5};
Curve Loop(6) = {3, 11, -7, -12};    // y = 1
Plane Surface(6) = {6};
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};

Transfinite Curve{1, 3, 5, 7} = 3;
Transfinite Curve{2, 4, 6, 8} = 3;
Transfinite Curve{9, 10, 11, 12} = 2;
Transfinite Surface{1, 2, 3, 4, 5, 6};
Recombine Surface{1, 2, 3, 4, 5, 6};
Transfinite Volume{1};

If (groups)
  If (volume_group)
    Physical Volume("BLOCK") = {1};
  EndIf
  Physical Surface("FIXED") = {3};
  Physical Surface("LOADED") = {4};
  Physical Surface("Top face") = {2};
  Physical Point("corner") = {7};
  Physical Curve(7) = {1};
EndIf
