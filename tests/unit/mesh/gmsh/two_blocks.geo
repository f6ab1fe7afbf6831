// Two unit cubes side by side, [0, 2] x [0, 1] x [0, 1], meshed with 2 x 2 x 2 hexahedra each
// (transfinite, recombined); the test mesh of GmshTest.cpp. Regenerate the committed .msh with
//   gmsh -3 -format msh41 two_blocks.geo -o two_blocks.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Coherence;  // one shared face at x = 1: a conforming mesh
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
e = 1e-6;
Physical Volume("steel") = Volume In BoundingBox{-e, -e, -e, 1 + e, 1 + e, 1 + e};
Physical Volume("rubber") = Volume In BoundingBox{1 - e, -e, -e, 2 + e, 1 + e, 1 + e};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
Physical Surface("right") = Surface In BoundingBox{2 - e, -e, -e, 2 + e, 1 + e, 1 + e};
Physical Surface("top") = Surface In BoundingBox{-e, 1 - e, -e, 2 + e, 1 + e, 1 + e};
Physical Surface(7) = Surface In BoundingBox{-e, -e, 1 - e, 2 + e, 1 + e, 1 + e};  // unnamed: "surface_7"
Physical Curve("bottom_back_edge") = Curve In BoundingBox{-e, -e, -e, 2 + e, e, e};
Physical Point("origin") = Point In BoundingBox{-e, -e, -e, e, e, e};
