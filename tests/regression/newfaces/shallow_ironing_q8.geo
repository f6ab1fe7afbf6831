// The shallow ironing mesh (inputs/verification/shallow_ironing.geo) with second-order incomplete cells:
// QUAD8 slab and die, 3-node edges on the contact surfaces (the die's arc, the slab's top). The committed
// coarse mesh of tests/regression/newfaces/CMakeLists.txt (Gmsh 4.8):
//   gmsh -2 -format msh41 -setnumber nx 60 -setnumber ny 10 -setnumber grade 6 -setnumber na 12 -setnumber nd 5 \
//        shallow_ironing_q8.geo -o shallow_ironing_coarse_q8.msh
Include "../../../inputs/verification/shallow_ironing.geo";
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
