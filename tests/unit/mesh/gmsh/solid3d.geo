// The 3D families of GmshTest.cpp's node-order tests, one small mesh per run of Gmsh:
//   kind = 0: tetrahedra of the box [0, 2] x [0, 1] x [0, 1] (unstructured, a few dozen);
//   kind = 1: 2 x 2 x 2 hexahedra of the box [0, 1]^3 (transfinite, recombined);
//   kind = 2: hexahedra on [0, 1] x [0, 1] and prisms on [1, 2] x [0, 1], extruded 2 layers to z = 1
//             (one physical volume holding both: two blocks "body_hex..", "body_wedge..").
// Element order 1 or 2; incomplete = 1 makes the 20-node hexahedra and 15-node prisms, 0 the 27-node
// hexahedra. Physical surfaces "bottom" (z = 0), "top" (z = 1), "left" (x = 0), "right" (x = 1 or 2) and
// "south" (y = 0). Regenerate with
// tests/unit/mesh/gmsh/make_meshes.sh.
DefineConstant[ kind = 0, order = 1, incomplete = 0 ];
e = 1e-6;
If (kind == 0)
  SetFactory("OpenCASCADE");
  Box(1) = {0, 0, 0, 2, 1, 1};
  Mesh.MeshSizeMin = 0.6;
  Mesh.MeshSizeMax = 0.6;
ElseIf (kind == 1)
  SetFactory("OpenCASCADE");
  Box(1) = {0, 0, 0, 1, 1, 1};
  Transfinite Curve{:} = 3;
  Transfinite Surface{:};
  Recombine Surface{:};
  Transfinite Volume{:};
Else
  Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
  Point(5) = {2, 0, 0}; Point(6) = {2, 1, 0};
  Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
  Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
  Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
  Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
  Transfinite Curve{1, 2, 3, 4, 5, 6, 7} = 3;
  Transfinite Surface{1};
  Recombine Surface{1};
  Extrude {0, 0, 1} { Surface{1, 2}; Layers{2}; Recombine; }
EndIf
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = incomplete;
Physical Volume("body") = Volume{:};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 2 + e, 1 + e, e};
Physical Surface("top") = Surface In BoundingBox{-e, -e, 1 - e, 2 + e, 1 + e, 1 + e};
xmax = kind == 1 ? 1 : 2;
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
Physical Surface("right") = Surface In BoundingBox{xmax - e, -e, -e, xmax + e, 1 + e, 1 + e};
Physical Surface("south") = Surface In BoundingBox{-e, -e, -e, 2 + e, e, 1 + e};
