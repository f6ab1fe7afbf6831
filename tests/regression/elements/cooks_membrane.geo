// Cook's membrane (Cook 1974): the trapezoid A (0, 0), B (48, 44), C (48, 60), D (0, 44), clamped on
// AD (x = 0), a uniform vertical shear on BC (x = 48). A structured n x n grid (tests/regression/elements/
// cooks_membrane.py makes every variant):
//   dim = 2: the plane mesh; cells = 1 quadrilaterals, 0 triangles;
//   dim = 3: the slab 0 <= z <= 1, one layer; cells = 1 hexahedra, 0 tetrahedra (6 per grid cell),
//            2 prisms (the grid's triangles extruded);
//   order 1 or 2; incomplete = 1: QUAD8 / HEX20 / PRISM15, 0: QUAD9 / HEX27.
// Physical groups: "clamped" (AD, or its face), "loaded" (BC, or its face), "corner" (C, or the edge
// through C), "front" and "back" (3D: z = 0 and z = 1), "body".
DefineConstant[ n = 4, dim = 2, cells = 1, order = 1, incomplete = 1 ];
Point(1) = {0, 0, 0}; Point(2) = {48, 44, 0}; Point(3) = {48, 60, 0}; Point(4) = {0, 44, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1} = {1, 2, 3, 4};
If (dim == 2)
  If (cells == 1)
    Recombine Surface{1};
  EndIf
  Physical Curve("clamped") = {4};
  Physical Curve("loaded") = {2};
  Physical Point("corner") = {3};
  Physical Surface("body") = {1};
Else
  Point(5) = {0, 0, 1}; Point(6) = {48, 44, 1}; Point(7) = {48, 60, 1}; Point(8) = {0, 44, 1};
  Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
  Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
  Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
  Curve Loop(3) = {1, 10, -5, -9}; Plane Surface(3) = {3};
  Curve Loop(4) = {2, 11, -6, -10}; Plane Surface(4) = {4};
  Curve Loop(5) = {3, 12, -7, -11}; Plane Surface(5) = {5};
  Curve Loop(6) = {4, 9, -8, -12}; Plane Surface(6) = {6};
  Surface Loop(1) = {1, 2, 3, 4, 5, 6}; Volume(1) = {1};
  Transfinite Curve{5, 6, 7, 8} = n + 1;
  Transfinite Curve{9, 10, 11, 12} = 2;
  Transfinite Surface{2} = {5, 6, 7, 8};
  Transfinite Surface{3} = {1, 2, 6, 5}; Transfinite Surface{4} = {2, 3, 7, 6};
  Transfinite Surface{5} = {3, 4, 8, 7}; Transfinite Surface{6} = {1, 5, 8, 4};
  Transfinite Volume{1} = {1, 2, 3, 4, 5, 6, 7, 8};
  If (cells == 1)
    Recombine Surface{1:6};
  ElseIf (cells == 2)
    Recombine Surface{3:6};
  EndIf
  Physical Surface("clamped") = {6};
  Physical Surface("loaded") = {4};
  Physical Curve("corner") = {11};
  Physical Surface("front") = {1};
  Physical Surface("back") = {2};
  Physical Volume("body") = {1};
EndIf
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = incomplete;
