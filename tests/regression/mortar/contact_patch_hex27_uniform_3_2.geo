// The blocks of inputs/verification/contact_patch_3d.xml (lower [0,1] x [0,0.5] x [0,1] under upper
// [0,1] x [0.5,1] x [0,1], no shared nodes) as Gmsh second-order hexahedra with centre nodes (HEX27, QUAD9
// contact faces) on NON-MATCHING UNIFORM faces: the lower block 3 x 1 x 3 cells, the upper 2 x 1 x 2. The
// two faces' quarter lines coincide at x = 0.5 and z = 0.5 (the lower's middle cell's centre lines, the
// upper's cell edges): the coincident piece edges of docs/theory-contact.md §13.2, where Newton stalled
// before the clip's snap was made consistent (tests/regression/mortar). The graded variant of
// tests/regression/newfaces keeps those lines apart. Physical groups as contact_patch_hex27.geo.
//   gmsh -3 -format msh41 contact_patch_hex27_uniform_3_2.geo -o contact_patch_hex27_uniform_3_2.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.5, 1};
Box(2) = {0, 0.5, 0, 1, 0.5, 1};
names[] = Str("lower", "upper");
e = 1e-6;
For v In {1 : 2}
  y0 = 0.5 * (v - 1);
  faces() = Abs(Boundary{ Volume{v}; });
  For k In {0 : #faces() - 1}
    bb() = BoundingBox Surface{faces(k)};
    If (bb(3) - bb(0) < e && bb(0) < e)
      Physical Surface(Sprintf(StrCat(names(v - 1), "_left"))) = {faces(k)};
    ElseIf (bb(3) - bb(0) < e)
      Physical Surface(Sprintf(StrCat(names(v - 1), "_right"))) = {faces(k)};
    ElseIf (bb(4) - bb(1) < e && Fabs(bb(1) - y0) < e)
      Physical Surface(Sprintf(StrCat(names(v - 1), "_bottom"))) = {faces(k)};
    ElseIf (bb(4) - bb(1) < e)
      Physical Surface(Sprintf(StrCat(names(v - 1), "_top"))) = {faces(k)};
    ElseIf (bb(5) - bb(2) < e && bb(2) < e)
      Physical Surface(Sprintf(StrCat(names(v - 1), "_back"))) = {faces(k)};
    Else
      Physical Surface(Sprintf(StrCat(names(v - 1), "_front"))) = {faces(k)};
    EndIf
  EndFor
  Physical Volume(Sprintf(names(v - 1))) = {v};
EndFor
Transfinite Curve{:} = 4;
upperCurves() = Abs(Boundary{ Boundary{ Volume{2}; } });
Transfinite Curve{upperCurves()} = 3;
edgesY() = Curve In BoundingBox{-e, -e, -e, 1 + e, 1 + e, 1 + e};
For k In {0 : #edgesY() - 1}
  bb() = BoundingBox Curve{edgesY(k)};
  If (bb(4) - bb(1) > e)
    Transfinite Curve{edgesY(k)} = 2;
  EndIf
EndFor
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
