// fault_bend.geo: the fault-bend model of Xing, Mora & Makinouchi (ICCS 2003), section 3:
// a 300 x 300 x 50 mm plate cut by a fault bent by 5.6 degrees at its centre E, meshed as TWO
// independent blocks of 8-node hexahedra (the fault faces of the two blocks share no nodes).
//
//   gmsh -3 -format msh41 fault_bend.geo -o fault_bend.msh                     (default mesh)
//   gmsh -3 -format msh41 -setnumber h_fault 5 -setnumber h_far 12 \
//        -setnumber layers 5 fault_bend.geo -o fault_bend.msh                   (finer)
//   gmsh -3 -format msh41 -setnumber bend_angle 0 fault_bend.geo -o flat.msh   (flat fault)
//
// What the paper gives and what is assumed: /work/shared/reference/fault_bend_model.md and
// doc/validation/fault_bend.md. Every assumed quantity is a variable below (-setnumber).
//
// Plan view (x right, y up, z = 0 .. thickness out of the page), default geometry:
//
//     (0,300) +-------------------------------G-----+ (300,300)      A: face y = 300
//             |        UPPER (upper-left)   /        |                B: face x = 300
//             |                           F          |                X0: x = 0, Y0: y = 0,
//             |                         /            |                Z0: z = 0
//             |                       E (150,150)    |
//             |                     /                |
//             |                   /   LOWER          |
//             |                 D     (lower-right)  |
//             C---------------/                      |
//       (0,14)|                                      |
//       (0,0) +--------------------------------------+ (300,0)
//
// The trace runs from C (on x = 0) through D, E, F to G (on y = 300). The half D-E leaves E
// towards x = 0 at fault_angle - bend_angle/2 to the x axis, the half E-F leaves E towards
// y = 300 at fault_angle + bend_angle/2. C-D and F-G (each tied_length long, measured along
// the trace) are the tied segments; D-E and E-F carry the friction law.
//
// Built-in kernel. The fault points and curves are defined twice, once for each block. gmsh
// merges coincident entities after an extrusion (Geometry.AutoCoherence), so the lower block
// is built and extruded at z + z_build_offset, and moved down to its place with
// Geometry.AutoCoherence = 0 once both blocks are extruded: the two blocks then share no
// point, curve or node, and each is meshed on its own.
//
// Mesh: each block's x-y face is meshed with quadrangles (Frontal-Delaunay triangles, full-quad
// recombination) and extruded through the thickness in `layers` layers of hexahedra.
// Along the fault the node spacing is uniform on each segment, at most h_fault on the upper
// (slave) side and at most h_fault * lower_fault_factor on the lower (master) side (an even
// number of elements per segment). With the default lower_fault_factor = 1 the fault nodes of
// the two sides coincide in position (still distinct nodes): matching fault nodes, which pass
// the contact patch test (issue 19; doc/validation/fault_bend_paper_law.md, section 8.5). With
// lower_fault_factor = 1.25 (the default before issue 19) they match only at C, D, E, F, G and
// where the two divisions happen to agree. Away from
// the fault the in-plane size grows linearly from h_fault to h_far over the distance h_grading.
// gmsh warns "Full-quad recombination only compatible with transfinite meshes if those are
// performed first" once per fault and boundary curve: expected, the mesh is checked by
// post/check_fault_mesh.py.
//
// Physical groups (fcs3d set and surface names are the upper-cased names):
//   volumes  UPPER, LOWER                               element sets (and node sets)
//   surfaces A (y = 300, parts of both blocks), B (x = 300), X0 (x = 0, both blocks),
//            Y0 (y = 0), Z0 (z = 0, both blocks)         element-face surfaces and node sets
//            CD_UPPER, CD_LOWER, DE_UPPER, DE_LOWER,
//            EF_UPPER, EF_LOWER, FG_UPPER, FG_LOWER      the two sides of each fault segment
//            DF_UPPER, DF_LOWER                          D-E and E-F together, each side
// When the trace ends exactly at a corner (bend_angle = 0 with fault_angle = 45: C = (0,0),
// G = (300,300)) the lower block has no face on x = 0 or y = 300; X0 and A then hold only the
// upper block's faces.

// ---------------------------------------------------------------- parameters (-setnumber)
If (!Exists(bend_angle))
  bend_angle = 5.6;       // degrees; 0 gives the flat fault
EndIf
If (!Exists(fault_angle))
  fault_angle = 45;       // degrees, mean direction of the trace from the x axis
EndIf
If (!Exists(xE))
  xE = 150;               // mm, the bend E
EndIf
If (!Exists(yE))
  yE = 150;
EndIf
If (!Exists(tied_length))
  tied_length = 30;       // mm, length of C-D and of F-G along the trace
EndIf
If (!Exists(width))
  width = 300;            // mm, plate size in x
EndIf
If (!Exists(height))
  height = 300;           // mm, plate size in y
EndIf
If (!Exists(thickness))
  thickness = 50;         // mm, plate size in z
EndIf
If (!Exists(h_fault))
  h_fault = 10;           // mm, in-plane element size along the fault (upper side)
EndIf
If (!Exists(lower_fault_factor))
  lower_fault_factor = 1;  // lower (master) side spacing / upper (slave) side spacing
EndIf
If (!Exists(h_far))
  h_far = 25;             // mm, in-plane element size far from the fault
EndIf
If (!Exists(h_grading))
  h_grading = 60;         // mm, distance from the fault over which the size grows to h_far
EndIf
If (!Exists(layers))
  layers = 3;             // elements through the thickness
EndIf

// ---------------------------------------------------------------- the fault trace
a1 = (fault_angle - bend_angle / 2) * Pi / 180;   // direction of D-E (E towards C, reversed)
a2 = (fault_angle + bend_angle / 2) * Pi / 180;   // direction of E-F
xC = 0;
yC = yE - xE * Tan(a1);
yG = height;
xG = xE + (height - yE) / Tan(a2);
length_CE = xE / Cos(a1);
length_EG = (height - yE) / Sin(a2);
eps = 1e-6 * width;
If (yC < -eps || yC > height - eps)
  Error("fault_bend.geo: the trace meets x = 0 at y = %g, outside the plate (0, %g)", yC, height);
  Exit;
EndIf
If (xG < eps || xG > width + eps)
  Error("fault_bend.geo: the trace meets y = %g at x = %g, outside the plate (0, %g)", height, xG, width);
  Exit;
EndIf
If (tied_length <= 0 || tied_length >= length_CE || tied_length >= length_EG)
  Error("fault_bend.geo: tied_length %g must be positive and shorter than C-E (%g) and E-G (%g)", tied_length, length_CE, length_EG);
  Exit;
EndIf
If (layers < 1 || h_fault <= 0 || h_far <= 0 || lower_fault_factor <= 0 || h_grading <= 0)
  Error("fault_bend.geo: layers, h_fault, h_far, h_grading and lower_fault_factor must be positive");
  Exit;
EndIf
yC = (yC < eps) ? 0 : yC;              // snap to the corner within round-off
xG = (xG > width - eps) ? width : xG;
corner_C = (yC == 0);                  // C at (0, 0): the lower block has no x = 0 face
corner_G = (xG == width);              // G at (width, height): no y = height face either
xD = xC + tied_length * Cos(a1);
yD = yC + tied_length * Sin(a1);
xF = xG - tied_length * Cos(a2);
yF = yG - tied_length * Sin(a2);
length_CD = tied_length;
length_DE = length_CE - tied_length;
length_EF = length_EG - tied_length;
length_FG = tied_length;
Printf("fault_bend.geo: C (%g, %g)  D (%g, %g)  E (%g, %g)  F (%g, %g)  G (%g, %g)", xC, yC, xD, yD, xE, yE, xF, yF, xG, yG);

// ---------------------------------------------------------------- 1D mesh (every curve)
// Every boundary curve of both blocks gets a prescribed, even number of segments: the
// full-quad recombination below meshes each face with twice the size and splits every element
// (a triangle into three quadrangles, a quadrangle into four), which needs the 1D meshes to be
// divisible by two. The fault segments are divided uniformly; an outer curve that touches the
// fault at one end is graded geometrically from h_fault there to about h_far at its other end.

// GradedCount: in g_length, g_fine, g_coarse; out g_n (even number of segments), g_q (ratio
// between consecutive segment lengths, >= 1, growing from the fine end).
Macro GradedCount
  If (g_length <= g_coarse || g_coarse <= g_fine)
    g_n = Ceil(g_length / g_fine - 1e-9);
    g_q = 1;
  Else
    g_q = (g_length - g_fine) / (g_length - g_coarse);
    g_n = Round(Log(g_coarse / g_fine) / Log(g_q)) + 1;
  EndIf
  g_n = 2 * Ceil(g_n / 2 - 1e-9);
  If (g_n < 2)
    g_n = 2;
  EndIf
Return

// UniformCount: in g_length, g_fine; out g_n (even number of segments of at most g_fine).
Macro UniformCount
  g_n = 2 * Ceil(g_length / g_fine / 2 - 1e-9);
  If (g_n < 2)
    g_n = 2;
  EndIf
Return

h_lower = h_fault * lower_fault_factor;
g_fine = h_fault;
g_length = length_CD;
Call UniformCount;
n_CD_u = g_n;
g_length = length_DE;
Call UniformCount;
n_DE_u = g_n;
g_length = length_EF;
Call UniformCount;
n_EF_u = g_n;
g_length = length_FG;
Call UniformCount;
n_FG_u = g_n;
g_fine = h_lower;
g_length = length_CD;
Call UniformCount;
n_CD_l = g_n;
g_length = length_DE;
Call UniformCount;
n_DE_l = g_n;
g_length = length_EF;
Call UniformCount;
n_EF_l = g_n;
g_length = length_FG;
Call UniformCount;
n_FG_l = g_n;
// Upper block: y = height from G to (0, height); x = 0 from (0, height) to C.
g_fine = h_fault;
g_coarse = h_far;
g_length = xG;
Call GradedCount;
n_top_u = g_n;
q_top_u = g_q;
g_length = height - yC;
Call GradedCount;
n_left_u = g_n;
q_left_u = g_q;
// Lower block: y = 0 from (0, 0) (or C) to (width, 0); x = width from (width, 0) to
// (width, height) (or G); the short pieces of y = height and x = 0 next to G and C.
g_length = width;
Call GradedCount;
n_bottom_l = g_n;
q_bottom_l = g_q;
g_length = yG;
Call GradedCount;
n_right_l = g_n;
q_right_l = g_q;
g_length = width - xG;
Call UniformCount;
n_top_l = g_n;
g_length = yC;
Call UniformCount;
n_left_l = g_n;

// ---------------------------------------------------------------- upper-left block
// Boundary, counter-clockwise: C D E F G (fault), G -> (0, height) (face A), -> C (face X0).
Point(1) = {xC, yC, 0, h_fault};
Point(2) = {xD, yD, 0, h_fault};
Point(3) = {xE, yE, 0, h_fault};
Point(4) = {xF, yF, 0, h_fault};
Point(5) = {xG, yG, 0, h_fault};
Point(6) = {0, height, 0, h_far};
Line(1) = {1, 2};   // C-D
Line(2) = {2, 3};   // D-E
Line(3) = {3, 4};   // E-F
Line(4) = {4, 5};   // F-G
Line(5) = {5, 6};   // y = height
Line(6) = {6, 1};   // x = 0
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Transfinite Curve{1} = n_CD_u + 1;
Transfinite Curve{2} = n_DE_u + 1;
Transfinite Curve{3} = n_EF_u + 1;
Transfinite Curve{4} = n_FG_u + 1;
Transfinite Curve{5} = n_top_u + 1 Using Progression q_top_u;
Transfinite Curve{6} = n_left_u + 1 Using Progression 1 / q_left_u;

// ---------------------------------------------------------------- lower-right block
// Built at z = z_build_offset (see the head of the file), moved to z = 0 after extrusion.
// Boundary, counter-clockwise: (0,0) -> (width,0) (Y0) -> (width,height) (B) -> G (A)
// -> F -> E -> D -> C (fault, reversed) -> (0,0) (X0). Corner points coinciding with C or G
// are left out.
// A power of two above twice the thickness: the two blocks never overlap while they are
// built, and z + offset - offset gives z back exactly for z = 0 (and to round-off otherwise).
z_build_offset = 2^Ceil(Log(4 * thickness) / Log(2));
zl = z_build_offset;
Point(11) = {xC, yC, zl, h_lower};
Point(12) = {xD, yD, zl, h_lower};
Point(13) = {xE, yE, zl, h_lower};
Point(14) = {xF, yF, zl, h_lower};
Point(15) = {xG, yG, zl, h_lower};
Point(16) = {width, 0, zl, h_far};
If (!corner_C)
  Point(17) = {0, 0, zl, h_far};
EndIf
If (!corner_G)
  Point(18) = {width, height, zl, h_far};
EndIf
Line(11) = {12, 11};   // D-C
Line(12) = {13, 12};   // E-D
Line(13) = {14, 13};   // F-E
Line(14) = {15, 14};   // G-F
Transfinite Curve{11} = n_CD_l + 1;
Transfinite Curve{12} = n_DE_l + 1;
Transfinite Curve{13} = n_EF_l + 1;
Transfinite Curve{14} = n_FG_l + 1;
// lower_loop[] lists the curves; lower_role[] says what each one is:
// 1 Y0, 2 B, 3 A, 4 X0, 10 + k fault segment k (1 C-D, 2 D-E, 3 E-F, 4 F-G).
If (corner_C)
  Line(15) = {11, 16};   // y = 0, from C = (0,0)
Else
  Line(15) = {17, 16};   // y = 0
EndIf
Transfinite Curve{15} = n_bottom_l + 1 Using Progression q_bottom_l;
lower_loop[] = {15};
lower_role[] = {1};
If (corner_G)
  Line(16) = {16, 15};   // x = width, up to G = (width, height)
  lower_loop[] += {16};
  lower_role[] += {2};
Else
  Line(16) = {16, 18};   // x = width
  Line(17) = {18, 15};   // y = height, from the corner to G
  Transfinite Curve{17} = n_top_l + 1;
  lower_loop[] += {16, 17};
  lower_role[] += {2, 3};
EndIf
Transfinite Curve{16} = n_right_l + 1 Using Progression 1 / q_right_l;
lower_loop[] += {14, 13, 12, 11};
lower_role[] += {14, 13, 12, 11};
If (!corner_C)
  Line(18) = {11, 17};   // x = 0, from C down to the corner
  Transfinite Curve{18} = n_left_l + 1;
  lower_loop[] += {18};
  lower_role[] += {4};
EndIf
Curve Loop(2) = {lower_loop[]};
Plane Surface(2) = {2};

// ---------------------------------------------------------------- 2D mesh size and algorithm
// Inside the faces the size grows with the distance from the fault (both blocks' fault
// curves, at their final place): h_fault on the fault, h_far from the distance h_grading on.
Field[1] = Distance;
Field[1].CurvesList = {1, 2, 3, 4, 11, 12, 13, 14};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_fault;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0;
Field[2].DistMax = h_grading;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromCurvature = 0;
// Frontal-Delaunay triangles, recombined into quadrangles, full-quad (see the 1D mesh above).
// With Debian's gmsh 4.8.4, plain recombination (Mesh.RecombinationAlgorithm = 1, blossom)
// leaves a few triangles even with an even number of boundary segments (prisms after the
// extrusion, which fcs3d does not read), and Mesh.Algorithm = 8 (Frontal-Delaunay for quads)
// crashes (segmentation fault) on this geometry.
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 3;
Mesh.Smoothing = 5;
Recombine Surface{1, 2};

// ---------------------------------------------------------------- extrusion through z
// Extrude returns: [0] the top surface, [1] the volume, [2 + i] the surface swept by the
// i-th curve of the base surface's loop (in the loop's order).
upper[] = Extrude {0, 0, thickness} { Surface{1}; Layers{layers}; Recombine; };
lower[] = Extrude {0, 0, thickness} { Surface{2}; Layers{layers}; Recombine; };
Geometry.AutoCoherence = 0;   // keep the two blocks apart when the lower one moves down
Translate {0, 0, -z_build_offset} { Volume{lower[1]}; }

Physical Volume("UPPER") = {upper[1]};
Physical Volume("LOWER") = {lower[1]};
Physical Surface("Z0") = {1, 2};
// Upper block: loop {C-D, D-E, E-F, F-G, y = height, x = 0}.
Physical Surface("CD_UPPER") = {upper[2]};
Physical Surface("DE_UPPER") = {upper[3]};
Physical Surface("EF_UPPER") = {upper[4]};
Physical Surface("FG_UPPER") = {upper[5]};
face_A[] = {upper[6]};
face_X0[] = {upper[7]};
// Lower block: by the roles recorded with its loop.
For i In {0 : #lower_loop[] - 1}
  s = lower[2 + i];
  If (lower_role[i] == 1)
    face_Y0[] = {s};
  EndIf
  If (lower_role[i] == 2)
    face_B[] = {s};
  EndIf
  If (lower_role[i] == 3)
    face_A[] += {s};
  EndIf
  If (lower_role[i] == 4)
    face_X0[] += {s};
  EndIf
  If (lower_role[i] == 11)
    face_CD_l = s;
  EndIf
  If (lower_role[i] == 12)
    face_DE_l = s;
  EndIf
  If (lower_role[i] == 13)
    face_EF_l = s;
  EndIf
  If (lower_role[i] == 14)
    face_FG_l = s;
  EndIf
EndFor
Physical Surface("CD_LOWER") = {face_CD_l};
Physical Surface("DE_LOWER") = {face_DE_l};
Physical Surface("EF_LOWER") = {face_EF_l};
Physical Surface("FG_LOWER") = {face_FG_l};
// The whole frictional part D-F of each side (D-E and E-F together), for a single contact
// pair in which the slave nodes at the bend E are one node each (with two pairs, DE and EF,
// the nodes at E are slaves of both).
Physical Surface("DF_UPPER") = {upper[3], upper[4]};
Physical Surface("DF_LOWER") = {face_DE_l, face_EF_l};
Physical Surface("A") = {face_A[]};
Physical Surface("B") = {face_B[]};
Physical Surface("X0") = {face_X0[]};
Physical Surface("Y0") = {face_Y0[]};
