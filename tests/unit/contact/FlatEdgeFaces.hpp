#pragma once
// The two coplanar master faces of the 3D stick patch's upper block (tests/regression/augmented/
// contact_patch_stick_3d.xml) that share an edge ending on the free boundary, as AugmentedFlatEdgeTest and
// FlatEdgeMasterRowTest take them: y = 0 here, outward normal −y (towards the lower block); face A = facet
// 1 over x ∈ [0.5, 1], z ∈ [0, 0.5], face B = facet 3 over z ∈ [0.5, 1]. They share the edge z = 0.5 from
// node index 21 (x = 0.5) to node index 26 (x = 1, Exodus node 27); `lift` moves that end in y.
#include "ElementTestTools.hpp"

namespace flat_edge {

using Face = cc::MasterFacetNodes<cc::Quad4Facet>;
using P3 = Vector<3>;

inline Face faceA(double lift) {
  return Face{1, {20, 25, 26, 21}, {P3{0.5, 0, 0}, P3{1, 0, 0}, P3{1, lift, 0.5}, P3{0.5, 0, 0.5}}};
}
inline Face faceB(double lift) {
  return Face{3, {21, 26, 27, 22}, {P3{0.5, 0, 0.5}, P3{1, lift, 0.5}, P3{1, 0, 1}, P3{0.5, 0, 1}}};
}
constexpr int kFreeEndOnA = 2, kFreeEndOnB = 1;  // the shared edge's free end's place in each face

}  // namespace flat_edge
