// kinds.geo: the box [0,2] x [0,1] x [0,1] of tests/integration/gmsh_kinds.sh, meshed with
// one kind of element or two: shape = 0 tetrahedra, 1 prisms, 2 hexahedra, 3 hexahedra for
// x < 1 and prisms for x > 1 (conforming: both extruded from a quad and a triangle mesh sharing
// the line x = 1). Order 1 or 2 from the command line (-order 2 with
// Mesh.SecondOrderIncomplete = 1 for the 10-, 15- and 20-node kinds).
// Physical groups: volume BLOCK; surfaces XMIN, XMAX, YMIN, ZMIN (the faces x = 0, x = 2,
// y = 0, z = 0) and MID, the internal surface x = 1 between the two extruded parts (its
// elements' normal is +x: line 7 from (1, 0) to (1, 1) swept along +z).
If (!Exists(shape))
  shape = 2;
EndIf
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {2, 1, 0};
Point(5) = {1, 1, 0};
Point(6) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Curve{1, 2, 4, 5} = 3;
Transfinite Curve{3, 6, 7} = 3;
If (shape == 2 || shape == 3)
  Transfinite Surface{1};
  Recombine Surface{1};
EndIf
If (shape == 2)
  Transfinite Surface{2};
  Recombine Surface{2};
EndIf
If (shape == 0)
  Mesh.CharacteristicLengthMax = 0.4;
  out[] = Extrude{0, 0, 1}{Surface{1, 2};};
Else
  out[] = Extrude{0, 0, 1}{Surface{1, 2}; Layers{2}; Recombine;};
EndIf
e = 1e-6;
Physical Volume("BLOCK") = Volume{:};
Physical Surface("XMIN") = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
Physical Surface("XMAX") = Surface In BoundingBox{2 - e, -e, -e, 2 + e, 1 + e, 1 + e};
Physical Surface("YMIN") = Surface In BoundingBox{-e, -e, -e, 2 + e, e, 1 + e};
Physical Surface("ZMIN") = Surface In BoundingBox{-e, -e, -e, 2 + e, 1 + e, e};
Physical Surface("MID") = Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e};
