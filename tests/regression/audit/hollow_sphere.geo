// An octant of a hollow sphere, inner radius 1, outer radius 2, centred at the origin (x, y, z >= 0):
// Lame's sphere under internal pressure (tests/regression/audit/README.md). Tetrahedra of element size h
// (gmsh -3 -setnumber h 0.35 -setnumber order 2 hollow_sphere.geo -o hollow_sphere_tet10.msh).
SetFactory("OpenCASCADE");
DefineConstant[h = 0.35, order = 2];
Sphere(1) = {0, 0, 0, 2.0, 0, Pi/2, Pi/2};
Sphere(2) = {0, 0, 0, 1.0, 0, Pi/2, Pi/2};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 0;
e = 1e-6;
inner() = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, 1 + e};
sx() = Surface In BoundingBox{-e, -e, -e, e, 2 + e, 2 + e};
sy() = Surface In BoundingBox{-e, -e, -e, 2 + e, e, 2 + e};
sz() = Surface In BoundingBox{-e, -e, -e, 2 + e, 2 + e, e};
outer() = Abs(Boundary{Volume{3};});
outer() -= {inner(), sx(), sy(), sz()};
Physical Volume("shell") = {3};
Physical Surface("inner") = inner();
Physical Surface("outer") = outer();
Physical Surface("symmetry_x") = sx();
Physical Surface("symmetry_y") = sy();
Physical Surface("symmetry_z") = sz();
