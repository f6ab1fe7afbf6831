// The block of inputs/punch_3d.xml, [0, 100] x [0, 100] x [0, 50], meshed by Gmsh with 4 x 4 x 2 hexahedra
// (transfinite, recombined), its physical groups named as the Box generator names its sets: left/right
// (x), bottom/top (y), back/front (z). The test mesh of tests/regression/contact3d (a contact deck on a
// Gmsh mesh gives the generated box's answer). Regenerate the committed .msh with
//   gmsh -3 -format msh41 punch_block.geo -o punch_block.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 100, 100, 50};
e = 1e-6;
Transfinite Curve{:} = 5;
Transfinite Curve{Curve In BoundingBox{-e, -e, -e, 100 + e, 100 + e, 50 + e}} = 5;
Transfinite Curve{Curve In BoundingBox{-e, -e, -e, e, e, 50 + e}} = 3;
Transfinite Curve{Curve In BoundingBox{100 - e, -e, -e, 100 + e, e, 50 + e}} = 3;
Transfinite Curve{Curve In BoundingBox{-e, 100 - e, -e, e, 100 + e, 50 + e}} = 3;
Transfinite Curve{Curve In BoundingBox{100 - e, 100 - e, -e, 100 + e, 100 + e, 50 + e}} = 3;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
Physical Volume("block") = {1};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, 100 + e, 50 + e};
Physical Surface("right") = Surface In BoundingBox{100 - e, -e, -e, 100 + e, 100 + e, 50 + e};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 100 + e, e, 50 + e};
Physical Surface("top") = Surface In BoundingBox{-e, 100 - e, -e, 100 + e, 100 + e, 50 + e};
Physical Surface("back") = Surface In BoundingBox{-e, -e, -e, 100 + e, 100 + e, e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, 50 - e, 100 + e, 100 + e, 50 + e};
