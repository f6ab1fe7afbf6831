// The blocks of inputs/verification/contact_patch_mortar.xml (lower [0,1] x [0,0.5] under upper
// [0,1] x [0.5,1], no shared nodes) as Gmsh second-order quadrilaterals with centre nodes (QUAD9 cells,
// 3-node contact sides), nl x 2 lower cells and nu x 2 upper ones (non-matching along x):
//   gmsh -2 -format msh41 -setnumber nl 3 -setnumber nu 2 contact_contact_patch_q9.geo -o contact_patch_q9_3_2.msh
If (!Exists(nl))
  nl = 3;
EndIf
If (!Exists(nu))
  nu = 2;
EndIf
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.RecombineAll = 1;
names[] = Str("lower", "upper");
For v In {0 : 1}
  y0 = 0.5 * v;
  p1 = newp; Point(p1) = {0, y0, 0};
  p2 = newp; Point(p2) = {1, y0, 0};
  p3 = newp; Point(p3) = {1, y0 + 0.5, 0};
  p4 = newp; Point(p4) = {0, y0 + 0.5, 0};
  bottom = newl; Line(bottom) = {p1, p2};
  right = newl; Line(right) = {p2, p3};
  top = newl; Line(top) = {p3, p4};
  left = newl; Line(left) = {p4, p1};
  loop = newll; Curve Loop(loop) = {bottom, right, top, left};
  s = news; Plane Surface(s) = {loop};
  n = (v == 0) ? nl : nu;
  Transfinite Curve{bottom, top} = n + 1;
  Transfinite Curve{left, right} = 3;
  Transfinite Surface{s};
  Recombine Surface{s};
  Physical Curve(Sprintf(StrCat(names(v), "_bottom"))) = {bottom};
  Physical Curve(Sprintf(StrCat(names(v), "_right"))) = {right};
  Physical Curve(Sprintf(StrCat(names(v), "_top"))) = {top};
  Physical Curve(Sprintf(StrCat(names(v), "_left"))) = {left};
  Physical Surface(Sprintf(names(v))) = {s};
EndFor
