// The 2D families of GmshTest.cpp's node-order tests: the rectangle [0, 2] x [0, 1] in the plane z = 0,
// quadrilaterals on [0, 1] (2 x 2, transfinite, recombined) and triangles on [1, 2] (unstructured), in
// one physical surface "plate" (two blocks "plate_quad..", "plate_tri.."); physical lines "left"
// (x = 0) and "right" (x = 2). Element order 1 or 2; incomplete = 1 makes 8-node quadrilaterals, 0 the
// 9-node ones. Regenerate with tests/unit/mesh/gmsh/make_meshes.sh.
DefineConstant[ order = 1, incomplete = 0 ];
e = 1e-6;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {2, 0, 0}; Point(6) = {2, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4, 5, 6, 7} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = incomplete;
Physical Surface("plate") = {1, 2};
Physical Curve("left") = {4};
Physical Curve("right") = {6};
