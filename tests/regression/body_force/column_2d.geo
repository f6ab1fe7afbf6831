// A column [0, 0.5] x [0, 2] (the body-force regression, tests/regression/body_force/CMakeLists.txt) as
// Gmsh's structured quadratic quadrilaterals, QUAD9: 2 x ny cells, the centre nodes Gmsh places.
// gmsh -2 -setnumber ny 4 column_2d.geo -o column_q9.msh
DefineConstant[ny = 4];
Point(1) = {0, 0, 0};
Point(2) = {0.5, 0, 0};
Point(3) = {0.5, 2, 0};
Point(4) = {0, 2, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Physical Surface("column") = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
