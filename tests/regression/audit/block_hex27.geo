// The block [0, 1] x [0, 0.5] x [0, 1] of press_slide_quadratic_3d.xml as 4 x 4 x 4 Gmsh HEX27 (complete second
// order: QUAD9 faces), bottom y = 0, top y = 0.5 (press_hex27.xml):
//   gmsh -3 block_hex27.geo -o block_hex27.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.5, 1};
Transfinite Curve{:} = 5;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
e = 1e-6;
Physical Volume("block") = {1};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
Physical Surface("top") = Surface In BoundingBox{-e, 0.5 - e, -e, 1 + e, 0.5 + e, 1 + e};
