// The section of inputs/verification/hertz_axisymmetric.xml's body (r from 1 to 10, 270 to 360 degrees) as structured
// QUAD8 (incomplete = 1) or QUAD9 (incomplete = 0), or TRI6 (quads = 0: each quadrilateral cut in two), graded
// towards the pole and the surface:
//   gmsh -2 hertz_section.geo -o hertz_section_q8.msh
//   gmsh -2 -setnumber incomplete 0 hertz_section.geo -o hertz_section_q9.msh
//   gmsh -2 -setnumber quads 0 hertz_section.geo -o hertz_section_tri6.msh
DefineConstant[nr = 20, na = 30, incomplete = 1, quads = 1, pr = 0.87, pa = 0.9];
Point(1) = {0, 0, 0};
Point(2) = {0, -1, 0};
Point(3) = {0, -10, 0};
Point(4) = {10, 0, 0};
Point(5) = {1, 0, 0};
Line(1) = {2, 3};        // axis ('start')
Circle(2) = {3, 1, 4};   // outer
Line(3) = {4, 5};        // equator ('end')
Circle(4) = {5, 1, 2};   // inner
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1} = nr + 1 Using Progression pr;
Transfinite Curve{3} = nr + 1 Using Progression 1/pr;
Transfinite Curve{2} = na + 1 Using Progression 1/pa;
Transfinite Curve{4} = na + 1 Using Progression pa;
Transfinite Surface{1};
If (quads)
  Recombine Surface{1};
EndIf
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = incomplete;
Physical Surface("cylinder") = {1};
Physical Curve("start") = {1};
Physical Curve("outer") = {2};
Physical Curve("end") = {3};
Physical Curve("inner") = {4};
