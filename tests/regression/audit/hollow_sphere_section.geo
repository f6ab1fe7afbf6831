// The section of a hollow sphere a = 1 <= r <= b = 2 in x >= 0, y >= 0 (x the radius, y the axis): revolved
// about y it is the upper half of Lame's sphere (tests/regression/audit/hollow_sphere_axisymmetric.xml).
// kind = 0: quadratic triangles (TRI6) of size h; kind = 1: a structured grid of n x 2n quadrilaterals,
// QUAD8 (incomplete = 1) or QUAD9 (incomplete = 0). Mid-edge nodes of the arcs lie on the circles.
//   gmsh -2 -setnumber kind 0 -setnumber h 0.2 hollow_sphere_section.geo -o hollow_sphere_tri6.msh
//   gmsh -2 -setnumber kind 1 -setnumber n 3 -setnumber incomplete 1 hollow_sphere_section.geo -o hollow_sphere_q8.msh
DefineConstant[kind = 0, h = 0.2, n = 3, incomplete = 1];
a = 1.0;
b = 2.0;
Point(1) = {0, 0, 0, h};
Point(2) = {a, 0, 0, h};
Point(3) = {b, 0, 0, h};
Point(4) = {0, b, 0, h};
Point(5) = {0, a, 0, h};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (kind == 1)
  Transfinite Curve{1, 3} = n + 1;
  Transfinite Curve{2, 4} = 2 * n + 1;
  Transfinite Surface{1};
  Recombine Surface{1};
EndIf
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = incomplete;
Physical Surface("shell") = {1};
Physical Curve("equator") = {1};
Physical Curve("outer") = {2};
Physical Curve("axis") = {3};
Physical Curve("inner") = {4};
