// block.geo: a 10 x 4 x 2 box meshed with a structured (transfinite) grid of 8-node hexahedra,
// the mesh fcs3d reads (element type 5 = C3D8; boundary quads give the element-face surfaces).
//
//   gmsh -3 -format msh41 block.geo -o block.msh                  (mesh size h = 0.5)
//   gmsh -3 -format msh41 -setnumber h 0.25 block.geo -o block.msh (finer)
//   add -bin for a binary file (smaller and faster to read)
//
// Built-in kernel, so coordinates are exact and the surface numbers below are fixed.
// Physical groups (fcs3d set names are the upper-case names):
//   volume  "BLOCK"   -> element set BLOCK and node set BLOCK
//   surface "FIXED"   (x = 0)     -> element-face surface FIXED and node set FIXED
//   surface "LOADED"  (x = L)     -> surface LOADED and node set LOADED
//   surface "TOP"     (z = H)     -> surface TOP and node set TOP
//   point   "CORNER"  (0, 0, 0)   -> node set CORNER
// With physical groups defined, gmsh saves only the elements of physical groups.

// Dimensions and mesh size; each can be changed from the command line with -setnumber.
If (!Exists(L))
  L = 10;
EndIf
If (!Exists(W))
  W = 4;
EndIf
If (!Exists(H))
  H = 2;
EndIf
If (!Exists(h))
  h = 0.5;
EndIf

// Number of element edges along each side (at least one).
nx = Ceil(L / h);
ny = Ceil(W / h);
nz = Ceil(H / h);
If (nx < 1)
  nx = 1;
EndIf
If (ny < 1)
  ny = 1;
EndIf
If (nz < 1)
  nz = 1;
EndIf

Point(1) = {0, 0, 0, h};
Point(2) = {L, 0, 0, h};
Point(3) = {L, W, 0, h};
Point(4) = {0, W, 0, h};
Point(5) = {0, 0, H, h};
Point(6) = {L, 0, H, h};
Point(7) = {L, W, H, h};
Point(8) = {0, W, H, h};

// Edges along x: 1, 3, 5, 7; along y: 2, 4, 6, 8; along z: 9, 10, 11, 12.
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
Curve Loop(2) = {5, 6, -7, -8};      // z = H
Plane Surface(2) = {2};
Curve Loop(3) = {4, 12, -8, -9};     // x = 0
Plane Surface(3) = {3};
Curve Loop(4) = {2, 11, -6, -10};    // x = L
Plane Surface(4) = {4};
Curve Loop(5) = {1, 10, -5, -9};     // y = 0
Plane Surface(5) = {5};
Curve Loop(6) = {3, 11, -7, -12};    // y = W
Plane Surface(6) = {6};
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};

Transfinite Curve{1, 3, 5, 7} = nx + 1;
Transfinite Curve{2, 4, 6, 8} = ny + 1;
Transfinite Curve{9, 10, 11, 12} = nz + 1;
Transfinite Surface{1, 2, 3, 4, 5, 6};
Recombine Surface{1, 2, 3, 4, 5, 6};
Transfinite Volume{1};

Physical Volume("BLOCK") = {1};
Physical Surface("FIXED") = {3};
Physical Surface("LOADED") = {4};
Physical Surface("TOP") = {2};
Physical Point("CORNER") = {1};
