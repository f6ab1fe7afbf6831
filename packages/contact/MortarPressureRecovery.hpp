#pragma once
// The nodal pressures a mortar interface reports (theory-contact.md §13, "The reported pressure"; output
// only: the forces and every answer are those of p_k = ε_N ⟨−g̃_k⟩ / A_k, eq. M6).
//
// The mortar traction is the field p_h = Σ_k Φ_k p_k over the slave surface (Φ_k: the slave facets' linear
// or bilinear functions, the weights of the weighted gaps; a quadratic face's flat pieces' ones), and the
// force it puts on slave node a is ∫ Φ_a p_h dA_0 = Σ_k M_ak p_k with the slave surface's mass matrix
// M_ak = ∫ Φ_a Φ_k dA_0. The coefficients p_k are the pressures of the weighted gaps; near a contact edge
// they carry the mode p_k ∝ (√3 − 2)^n (n nodes from the edge), which M maps to zero force in the interior
// (1 + 4r + r² = 0 on a uniform 2D line, r = √3 − 2), so the edge's mismatch with the true traction's
// square-root profile is free to ring inwards: on the Hertz cylinder ±1.9e-2 p0 at the last two closed
// nodes, still 2.8e-3 p0 four nodes (0.77 a) from the edge (verification-contact.md §9.6). The reported
// value is the field's mean over the node's support,
//
//     p̄_a = ∫ Φ_a p_h dA_0 / ∫ Φ_a dA_0 = Σ_k M_ak p_k / Σ_k M_ak,                         (M6′)
//
// the nodal force per tributary area, which is what node-to-segment reports (p_a = f_a / A_a): the ringing
// mode is annihilated away from the edge, a uniform pressure is kept exactly (every patch test), and
// Σ_a A_a p̄_a = Σ_k A_k p_k is the interface's force. The price: a smooth field is smeared by
// h² p″ / 6 (the lumped mass's). The model reports it at closed nodes only (PostProcessing: an open node
// shows 0, although the first one beside a closed node carries part of its traction, so that a positive
// pressure means a closed node as with node-to-segment). Mass matrices from the reference measures
// the interface keeps: exact on segments (a 3-node segment's two chords), triangles and a quadratic face's pieces; a Quad4 face as the
// parallelogram of its area (its row sums, not the exact ∫ Φ_a, normalise: uniform fields stay exact).
#include <cstddef>
#include <vector>

#include "contact/InterfaceSpec.hpp"

namespace contessa::contact {

/// The weights of eq. (M6′): per slave node a (its index in ContactInterfaceSpec::slaveNodes), the slave
/// nodes b of its facets and w_ab = M_ab / Σ_c M_ac (non-negative, summing to 1), as compressed rows.
struct MortarPressureRecovery {
  std::vector<std::size_t> rowStart;  ///< slaveNodes.size() + 1 entries
  std::vector<std::size_t> column;
  std::vector<double> weight;

  /// p̄_a = Σ_b w_ab p_b for every slave node, from every slave node's p_b.
  std::vector<double> apply(const std::vector<double>& pressure) const;
};

/// The weights of a mortar interface's slave surface (spec.mortar; its slave facets and their measures).
MortarPressureRecovery mortarPressureRecovery(const ContactInterfaceSpec& spec);

}  // namespace contessa::contact
