// A quarter of a thick-walled cylinder a = 10 <= r <= b = 20 (x, y >= 0), one layer 0 <= z <= 2 thick: Lame's
// cylinder in plane strain on curved quadratic hexahedra (hollow_cylinder_hex.xml). n x 2n x 1 cells, HEX27
// (incomplete = 0) or HEX20 (incomplete = 1); the mid-edge and face nodes of the arcs lie on the circles.
//   gmsh -3 -setnumber n 3 -setnumber incomplete 0 hollow_cylinder.geo -o hollow_cylinder_hex27.msh
DefineConstant[n = 3, incomplete = 0];
Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {20, 0, 0};
Point(4) = {0, 20, 0};
Point(5) = {0, 10, 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = 2 * n + 1;
Transfinite Surface{1};
Recombine Surface{1};
out[] = Extrude {0, 0, 2} {Surface{1}; Layers{1}; Recombine;};
// out[0] the top surface, out[1] the volume, out[2..5] the sides of curves 1..4
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = incomplete;
Physical Volume("wall") = {out[1]};
Physical Surface("start") = {out[2]};
Physical Surface("outer") = {out[3]};
Physical Surface("end") = {out[4]};
Physical Surface("inner") = {out[5]};
Physical Surface("back") = {1};
Physical Surface("front") = {out[0]};
