// The quarter tube of inputs/tube_bending_3d.xml (r = 100 ... 120 mm, 0 ... 90 degrees) as one layer
// 0 <= z <= 1 of a structured grid, nt elements through the wall and na around the arc:
//   cells = 1 hexahedra, 0 tetrahedra (Gmsh's split of the transfinite grid);
//   order 1 or 2; incomplete = 1: HEX20 / TETRA10, 0: HEX27.
// Mid-edge nodes lie on the arcs (curved elements). Physical groups as the Hollow Cylinder Sector's:
// "inner", "outer", "start" (the cut at 0 degrees, y = 0), "end" (at 90 degrees, x = 0), "back" (z = 0),
// "front" (z = 1), "faces_z" (both: u_z = 0 there is plane strain on hexahedra, whose layer is symmetric
// about z = 1/2; on tetrahedra the mid-edge nodes inside the layer are left free, a small departure), and
// the volume "tube". The committed meshes (Gmsh 4.8; tests/regression/newfaces/CMakeLists.txt):
//   gmsh -3 -format msh41 tube_section.geo -o tube_hex20.msh
//   gmsh -3 -format msh41 -setnumber cells 0 tube_section.geo -o tube_tet10.msh
DefineConstant[ nt = 4, na = 40, cells = 1, order = 2, incomplete = 1 ];
ri = 100; ro = 120;
Point(1) = {0, 0, 0};
Point(2) = {ri, 0, 0}; Point(3) = {ro, 0, 0}; Point(4) = {0, ro, 0}; Point(5) = {0, ri, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nt + 1;
Transfinite Curve{2, 4} = na + 1;
Transfinite Surface{1} = {2, 3, 4, 5};
If (cells == 1)
  Recombine Surface{1};
  out[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; Recombine; };
Else
  out[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; };
EndIf
// out[0] the front face z = 1, out[1] the volume, out[2..5] the sides of curves 1..4.
Physical Surface("start") = {out[2]};
Physical Surface("outer") = {out[3]};
Physical Surface("end") = {out[4]};
Physical Surface("inner") = {out[5]};
Physical Surface("back") = {1};
Physical Surface("front") = {out[0]};
Physical Surface("faces_z") = {1, out[0]};
Physical Volume("tube") = {out[1]};
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = incomplete;
