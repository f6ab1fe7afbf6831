// A bored roller with rounded ends on a fixed axle, pressed and then dragged by a rigid plate
// (inputs/roller_on_axle.xml): a CAD-style part made with the OpenCASCADE kernel (two cylinders
// subtracted, the outer end edges filleted), cut to its half z <= L/2 by the symmetry plane, meshed with
// second-order tetrahedra. Physical groups: "roller" (the volume), "outer" (the outer skin and fillet,
// which the plate touches), "bore" (on the axle), "symmetry_z" (z = L/2).
// Mesh: gmsh -3 -format msh41 roller_on_axle.geo -o roller_on_axle.msh   (Gmsh 4.8; -setnumber size S)
SetFactory("OpenCASCADE");
DefineConstant[ size = 2.5, order = 2 ];
R = 10; r = 4; L = 20; f = 2;
Cylinder(1) = {0, 0, 0, 0, 0, L, R};
Cylinder(2) = {0, 0, 0, 0, 0, L, r};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
edges() = Curve In BoundingBox{-R - 1, -R - 1, -1, R + 1, R + 1, L + 1};
ends() = {};
For k In {0 : #edges() - 1}
  bb() = BoundingBox Curve{edges(k)};
  If (bb(3) - bb(0) > 2 * R - 1e-6)  // the two outer circles, not the bore's
    ends() += edges(k);
  EndIf
EndFor
filleted() = Fillet{3}{ends()}{f};
Box(10) = {-R - 1, -R - 1, -1, 2 * R + 2, 2 * R + 2, L / 2 + 1};
BooleanIntersection(20) = { Volume{filleted(0)}; Delete; }{ Volume{10}; Delete; };
e = 1e-6;
symZ() = Surface In BoundingBox{-R - 1, -R - 1, L / 2 - e, R + 1, R + 1, L / 2 + e};
bore() = Surface In BoundingBox{-r - e, -r - e, -1, r + e, r + e, L};
all() = Surface In BoundingBox{-R - 1, -R - 1, -1, R + 1, R + 1, L};
outer() = all();
outer() -= symZ();
outer() -= bore();
Physical Volume("roller") = {20};
Physical Surface("outer") = {outer()};
Physical Surface("symmetry_z") = {symZ()};
Physical Surface("bore") = {bore()};
Mesh.MeshSizeMin = size; Mesh.MeshSizeMax = size;
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 1;
