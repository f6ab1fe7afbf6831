// Shallow ironing benchmark (Yang, Laursen and Meng 2005; Code_Aster SSNP153; solids4foam shallowIroning):
// geometry in mm, plane (z = 0). docs/verification-contact.md, "Shallow ironing", gives the sources.
//
//   foundation  [0, 12] x [0, 4], fixed at the bottom (physical curve "foundation_bottom"), its top
//               "foundation_top" the contact master;
//   die         1.2 mm wide, x in [0.2, 1.4]: a straight part y in [4.5, 5.4] over a circular bottom of
//               radius 0.75 (chord 1.2, sagitta 0.3, centre (0.8, 4.95)), lowest point (0.8, 4.2): an
//               initial gap of 0.2 mm. Its bottom arc and its front side (x = 1.4, the side leading the
//               slide: the slab's bow wave rises against it), "die_contact", are the contact slave (as the
//               solids4foam case's slave patch); its top "die_top" carries the prescribed motion.
//
// Two separate surfaces (no shared nodes): blocks "foundation" and "die". Quadrilaterals from transfinite
// recombined surfaces. Parameters (gmsh -setnumber NAME VALUE):
//   nx    foundation elements along x (uniform: the die slides over the whole top)
//   ny    foundation elements through the depth, graded by ratio "grade" (largest / smallest, the
//         smallest at the top)
//   na    die elements along the arc (and along its top), nd through its height
// The committed meshes (inputs/verification/make_shallow_ironing_meshes.sh):
//   shallow_ironing.msh         nx 120, ny 20, grade 6, na 24, nd 10   (foundation top 0.1 mm, arc 0.058 mm)
//   shallow_ironing_coarse.msh  nx 60,  ny 10, grade 6, na 12, nd 5    (the regression test's)
DefineConstant[ nx = 120, ny = 20, grade = 6, na = 24, nd = 10 ];

// Foundation
Point(1) = {0, 0, 0};
Point(2) = {12, 0, 0};
Point(3) = {12, 4, 0};
Point(4) = {0, 4, 0};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right, upwards
Line(3) = {3, 4};   // top
Line(4) = {1, 4};   // left, upwards (same direction as line 2, so one progression grades both)
Curve Loop(1) = {1, 2, 3, -4};
Plane Surface(1) = {1};

// Die: arc from (0.2, 4.5) through (0.8, 4.2) to (1.4, 4.5) about the centre (0.8, 4.95)
Point(11) = {0.2, 4.5, 0};
Point(12) = {1.4, 4.5, 0};
Point(13) = {1.4, 5.4, 0};
Point(14) = {0.2, 5.4, 0};
Point(15) = {0.8, 4.95, 0};
Circle(11) = {11, 15, 12};  // arc, left to right (the short way, below the centre)
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

// Progression r over ny elements with last / first = grade: r^(ny - 1) = 1 / grade (largest at the bottom).
r = Exp(-Log(grade) / (ny - 1));
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1 Using Progression r;
Transfinite Curve{11, 13} = na + 1;
Transfinite Curve{12, 14} = nd + 1;
Transfinite Surface{1} = {1, 2, 3, 4};
Transfinite Surface{2} = {11, 12, 13, 14};
Recombine Surface{1, 2};
Mesh.ElementOrder = 1;

Physical Surface("foundation") = {1};
Physical Surface("die") = {2};
Physical Curve("foundation_bottom") = {1};
Physical Curve("foundation_top") = {3};
Physical Curve("die_contact") = {11, 12};
Physical Curve("die_top") = {13};
