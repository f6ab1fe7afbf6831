#pragma once
// The tangent basis in which a 3D mortar slave node's weighted slip increment and tangential traction are
// 2-vectors (theory-contact.md §13, eq. M9′–M10′). The kernel (MortarFacetPair.hpp) integrates the slip
// increment as a 3-vector in the master's tangent planes; node k takes its components along an
// orthonormal pair (e_1, e_2) normal to n_k, the normalised sum of the unit normals of its slave facets
// at the last converged state (the averaged nodal normal of Popp, Gitterle, Gee & Wall 2010 and Gitterle
// et al. 2010, there taken at the current state). At the committed state the basis is a constant of the
// increment: the slip increments' components are then linear in the 3-vectors and their derivatives need
// none of the basis (Popp et al. linearise the current nodal normal and its tangents instead, which adds
// their derivatives in all the neighbouring slave nodes). At each commit the committed traction is
// carried into the new basis as a 3-vector (transportTraction), so the basis' choice of e_1 in the plane
// does not matter. In 2D the kernel's scalar slip is already along the master's tangent (MortarSegment.hpp,
// eq. M9): the "basis" is the 1 × 1 identity.
#include <array>
#include <cmath>
#include <vector>

#include "contact/SmallMatrix.hpp"

namespace contessa::contact {

/// The rows e_α of a slave node's tangent basis, over the kernel's slip entries.
template <int SlipDim, int Entries>
using MortarSlipBasis = std::array<Vector<Entries>, SlipDim>;

/// The unit normal of a flat 3- or 4-node facet from its corners (the area normal at its centre, as
/// LinearFacet::centreNormal).
inline Vector<3> linearFacetNormal(const std::vector<Vector<3>>& x) {
  const Vector<3> n = x.size() == 3 ? cross(subtract(x[1], x[0]), subtract(x[2], x[0]))
                                    : cross(subtract(x[2], x[0]), subtract(x[3], x[1]));
  const double length = norm(n);
  return length > 0.0 ? scaled(1.0 / length, n) : n;
}

/// An orthonormal (e_1, e_2) with e_1 × e_2 = n (n a unit vector): e_1 along the projection on the plane of
/// the coordinate axis least aligned with n (deterministic, so that every rank builds the same one).
inline MortarSlipBasis<2, 3> tangentBasis(const Vector<3>& n) {
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(n[c]) < std::abs(n[axis])) axis = c;
  Vector<3> e{};
  e[axis] = 1.0;
  Vector<3> e1 = subtract(e, scaled(dot(e, n), n));
  e1 = scaled(1.0 / norm(e1), e1);
  return {e1, cross(n, e1)};
}

/// Components of a tangential vector given in basis `from` in basis `to` (the committed traction at a
/// commit, whose node's basis turned with its normal): the 3-vector Σ t_α e_α projected on `to`.
inline Vector<2> transportTraction(const Vector<2>& t, const MortarSlipBasis<2, 3>& from, const MortarSlipBasis<2, 3>& to) {
  Vector<3> v{};
  for (int a = 0; a < 2; ++a) addScaled(v, t[a], from[a]);
  return {dot(v, to[0]), dot(v, to[1])};
}

}  // namespace contessa::contact
