// hertz_cylinder.geo: a cylinder pressed on a block, in plane strain (a slab one element
// thick in z; the decks hold every node in z). Used by tests/integration/contact/hertz.py
// (Hertz and Cattaneo-Mindlin tests, doc/validation/contact.md).
//
//   gmsh -3 -format msh41 -setnumber hc 0.1 hertz_cylinder.geo -o hertz.msh
//
// Section in the x-y plane (y up):
//   CAP:   the lower part of a cylinder of radius R whose lowest point is the origin: x in
//          [-Wc, Wc], bottom the circular arc y = R - sqrt(R^2 - x^2), top the line y = Hc.
//   BLOCK: x in [-Wb, Wb], y in [-Hb, 0].
// Both extruded by t = hc in z (one layer of hexahedra). The contact zone |x| <= xf (xf is
// rounded to a whole number of elements) has uniform element edges hc along the arc and along
// the block top, so that the meshes match there (up to the arc-length/x difference, below
// 0.2 % of hc); elsewhere the quadrangles (Frontal-Delaunay, blossom recombination) grow to
// hfar with the distance from the contact zone.
//
// Physical groups (fcs3d names): volumes CAP, BLOCK (element sets and node sets); surfaces
// CAP_BOTTOM (the arc: slave), CAP_TOP (loaded), BLOCK_TOP (master), BLOCK_BOTTOM (fixed).
// The block top has no geometry point at the origin (its middle curve runs from -xf to xf):
// gmsh merges coincident geometry points (Geometry.AutoCoherence), which would glue the
// cylinder's lowest node to the block.
If (!Exists(R))
  R = 20;
EndIf
If (!Exists(hc))
  hc = 0.1;
EndIf
If (!Exists(xf))
  xf = 1.6;
EndIf
If (!Exists(hfar))
  hfar = 2;
EndIf
If (!Exists(Wc))
  Wc = 10;
EndIf
If (!Exists(Hc))
  Hc = 10;
EndIf
If (!Exists(Wb))
  Wb = 15;
EndIf
If (!Exists(Hb))
  Hb = 15;
EndIf
t = hc;
nf = Round(xf / hc);
xf = nf * hc;
yarc = R - Sqrt(R * R - Wc * Wc);
yf = R - Sqrt(R * R - xf * xf);

// Cylinder part (CAP).
Point(1) = {0, R, 0, hfar};
Point(2) = {-Wc, yarc, 0, hfar};
Point(3) = {-xf, yf, 0, hc};
Point(4) = {0, 0, 0, hc};
Point(5) = {xf, yf, 0, hc};
Point(6) = {Wc, yarc, 0, hfar};
Point(7) = {Wc, Hc, 0, hfar};
Point(8) = {-Wc, Hc, 0, hfar};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Line(5) = {6, 7};
Line(6) = {7, 8};
Line(7) = {8, 2};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};

// Block.
Point(11) = {-Wb, -Hb, 0, hfar};
Point(12) = {Wb, -Hb, 0, hfar};
Point(13) = {Wb, 0, 0, hfar};
Point(14) = {xf, 0, 0, hc};
Point(16) = {-xf, 0, 0, hc};
Point(17) = {-Wb, 0, 0, hfar};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 16};
Line(16) = {16, 17};
Line(17) = {17, 11};
Curve Loop(2) = {11, 12, 13, 14, 16, 17};
Plane Surface(2) = {2};

// Uniform contact zone, graded elsewhere.
Transfinite Curve{2, 3} = nf + 1;
Transfinite Curve{14} = 2 * nf + 1;
Field[1] = Distance;
Field[1].CurvesList = {2, 3, 14};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = hfar;
Field[2].DistMin = 0.3;
Field[2].DistMax = 10;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
// Frontal-Delaunay (6) with blossom recombination: all quadrangles here. (Algorithm 8,
// Frontal-Delaunay for quads, crashes gmsh 4.8.4 with this background field.)
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Recombine Surface{1, 2};

cap[] = Extrude {0, 0, t} { Surface{1}; Layers{1}; Recombine; };
blk[] = Extrude {0, 0, t} { Surface{2}; Layers{1}; Recombine; };
// Extrude returns the top surface, the volume, then the lateral surfaces in the order of
// the curves of the loop: cap curves 1..7, block curves 11, 12, 13, 14, 16, 17.
Physical Volume("CAP") = {cap[1]};
Physical Volume("BLOCK") = {blk[1]};
Physical Surface("CAP_BOTTOM") = {cap[2], cap[3], cap[4], cap[5]};
Physical Surface("CAP_TOP") = {cap[7]};
Physical Surface("BLOCK_TOP") = {blk[4], blk[5], blk[6]};
Physical Surface("BLOCK_BOTTOM") = {blk[2]};
