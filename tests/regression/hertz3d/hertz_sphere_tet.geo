// The sphere of inputs/verification/hertz_sphere.xml (R = 50 mm, pole down at (0, 0, -50)) as an
// octant x >= 0, y >= 0, z <= 0 made with the OpenCASCADE kernel and meshed with tetrahedra, refined
// towards the pole: size `fine` within `reach` of the pole, growing to `coarse` at grade x reach
// (Gmsh's Distance and Threshold fields). Physical groups as the Sphere Octant generator's: "surface"
// (the spherical face, the contact slave), "symmetry_x" (x = 0), "symmetry_y" (y = 0), "equator"
// (z = 0, pushed), the volume "sphere".
// The committed meshes (Gmsh 4.8; hertz_sphere_tet.xml, tests/regression/hertz3d/CMakeLists.txt):
//   gmsh -3 -format msh41 -setnumber order 2 -setnumber fine 1.6 hertz_sphere_tet.geo -o hertz_sphere_tet10.msh
//   gmsh -3 -format msh41 -setnumber order 1 -setnumber fine 0.8 hertz_sphere_tet.geo -o hertz_sphere_tet4.msh
SetFactory("OpenCASCADE");
DefineConstant[ fine = 1.6, coarse = 12, reach = 12, grade = 2, order = 2 ];
R = 50;
Sphere(1) = {0, 0, 0, R, -Pi/2, 0, Pi/2};
e = 1e-6;
symX() = Surface In BoundingBox{-e, -R - 1, -R - 1, e, R + 1, R + 1};
symY() = Surface In BoundingBox{-R - 1, -e, -R - 1, R + 1, e, R + 1};
eq() = Surface In BoundingBox{-R - 1, -R - 1, -e, R + 1, R + 1, e};
surf() = Surface In BoundingBox{-R - 1, -R - 1, -R - 1, R + 1, R + 1, R + 1};
surf() -= symX();
surf() -= symY();
surf() -= eq();
Physical Volume("sphere") = {1};
Physical Surface("surface") = {surf()};
Physical Surface("symmetry_x") = {symX()};
Physical Surface("symmetry_y") = {symY()};
Physical Surface("equator") = {eq()};
pole() = Point In BoundingBox{-e, -e, -R - e, e, e, -R + e};
Field[1] = Distance; Field[1].PointsList = {pole()};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = fine; Field[2].SizeMax = coarse;
Field[2].DistMin = reach; Field[2].DistMax = grade * reach;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 1;
