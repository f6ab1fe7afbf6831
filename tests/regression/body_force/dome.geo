// A dome: the octant x, y, z >= 0 of the ball of radius 1, its flat quarter disc y = 0 the base it rests on
// (resting_dome_tet10.xml), as quadratic tetrahedra of size h, the mid-edge nodes of the sphere on it.
// gmsh -3 -setnumber h 0.3 dome.geo -o dome_tet10.msh
SetFactory("OpenCASCADE");
DefineConstant[h = 0.3];
Sphere(1) = {0, 0, 0, 1.0, 0, Pi/2, Pi/2};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Mesh.ElementOrder = 2;
Mesh.HighOrderOptimize = 0;
e = 1e-6;
sx() = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
sy() = Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
sz() = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
outer() = Abs(Boundary{Volume{1};});
outer() -= {sx(), sy(), sz()};
Physical Volume("dome") = {1};
Physical Surface("base") = sy();
Physical Surface("symmetry_x") = sx();
Physical Surface("symmetry_z") = sz();
Physical Surface("outer") = outer();
