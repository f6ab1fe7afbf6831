// A column [0, 0.5] x [0, 2] x [0, 0.5] (the body-force regression, tests/regression/body_force/CMakeLists.txt):
// its base (y = 0) meshed nx x nx, as quadrilaterals (wedges = 0) or split into triangles (wedges = 1), extruded
// along y in ny layers: HEX27 (order 2, complete) from the quadrilaterals, WEDGE6 / WEDGE15 (order 1 / 2,
// serendipity) from the triangles.
// gmsh -3 -setnumber ny 4 -setnumber wedges 0 -setnumber order 2 column_3d.geo -o column_hex27.msh
// gmsh -3 -setnumber ny 4 -setnumber wedges 1 -setnumber order 2 column_3d.geo -o column_wedge15.msh
// gmsh -3 -setnumber ny 4 -setnumber wedges 1 -setnumber order 1 column_3d.geo -o column_wedge6_4.msh
// gmsh -3 -setnumber nx 4 -setnumber ny 8 -setnumber wedges 1 -setnumber order 1 column_3d.geo -o column_wedge6_8.msh
DefineConstant[nx = 2, ny = 4, wedges = 0, order = 2];
Point(1) = {0, 0, 0};
Point(2) = {0.5, 0, 0};
Point(3) = {0.5, 0, 0.5};
Point(4) = {0, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = nx + 1;
Transfinite Surface{1};
If (wedges == 0)
  Recombine Surface{1};
EndIf
out[] = Extrude{0, 2, 0}{Surface{1}; Layers{ny}; Recombine;};
// out[0]: the top, out[1]: the volume, out[2..5]: the sides swept by lines 1..4 (z = 0, x = 0.5, z = 0.5, x = 0).
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = (wedges == 1) ? 1 : 0;
Physical Volume("column") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
Physical Surface("back") = {out[2]};
Physical Surface("right") = {out[3]};
Physical Surface("front") = {out[4]};
Physical Surface("left") = {out[5]};
// A side set of both face shapes (WEDGE6: the top's triangles, the side's quadrilaterals), for a load on mixed faces.
Physical Surface("top_and_right") = {out[0], out[3]};
