#pragma once
// Continuous collision detection for the tunnelling check (theory-contact.md §12): did a slave node
// pass through a master facet between the committed state (t = 0) and the trial state (t = 1)?
// Penalty contact (eq. 16) only sees a node that is in contact at the end of an increment: one that
// went right through a master in a large increment ends beyond its reach, or outside on the far side,
// and would be forgotten. Between the two states the node and every facet node are taken to move on
// straight lines, x(t) = (1 − t) x⁰ + t x¹.
//
// The facet is split into its flat pieces (Facet::flatPieces(): the segment itself, two triangles of a
// 4-node face). On a piece with vertices y_0 … y_{d−1} (d the space dimension) the signed volume
//
//     φ(t) = (x(t) − y_0(t)) · N(t),   N = Facet::areaNormal(y_1 − y_0, …, y_{d−1} − y_0),
//
// equals ‖N‖ g_N (eq. 4–5 on the piece's plane, positive in front of the master), and is a polynomial
// of degree d in t: a quadratic in 2D (a point against a moving segment), a cubic in 3D (a point against
// a moving triangle). Only the split into flat pieces is facet specific; the rest is written once.
#include <array>

#include "contact/MasterFacet.hpp"

namespace contessa::contact {

/// The node entered a facet from its front side (φ ≥ 0 at t = 0) and ends behind it.
struct SweptCrossing {
  bool crossed = false;
  double time = 0.0;  ///< t ∈ [0, 1] at which the node was on the facet (the last such crossing)
  int piece = -1;     ///< the flat piece it went through
};

/// Whether the node x⁰ → x¹ crosses the facet y⁰ → y¹ from the front to the back: on a flat piece,
/// φ(0) ≥ 0 > φ(1), the node lies inside the piece (barycentric coordinates within
/// [−insideTolerance, 1 + insideTolerance]) at the last root t* of φ in [0, 1], and at t = 1 it lies
/// behind the facet and inside it (its projection falls inside a piece with φ < 0). A node that grazes
/// past a free end, or that goes in and comes back out on the same side, has not crossed.
template <class Facet>
SweptCrossing sweptCrossing(const typename Facet::Point& slave0, const typename Facet::Point& slave1,
                            const std::array<typename Facet::Point, Facet::kNodes>& facet0,
                            const std::array<typename Facet::Point, Facet::kNodes>& facet1,
                            double insideTolerance = 1e-8);

/// Real roots in [0, 1] of c[0] + c[1] t + c[2] t² + c[3] t³ where the sign changes, ascending (exposed
/// for the unit tests; the crossing test needs only the last one).
std::array<double, 3> signChangeRootsInUnitInterval(const std::array<double, 4>& c, int& count);

extern template SweptCrossing sweptCrossing<Line2Facet>(const Line2Facet::Point&, const Line2Facet::Point&,
                                                        const std::array<Line2Facet::Point, 2>&,
                                                        const std::array<Line2Facet::Point, 2>&, double);
extern template SweptCrossing sweptCrossing<Quad4Facet>(const Quad4Facet::Point&, const Quad4Facet::Point&,
                                                        const std::array<Quad4Facet::Point, 4>&,
                                                        const std::array<Quad4Facet::Point, 4>&, double);
extern template SweptCrossing sweptCrossing<Line3Facet>(const Line3Facet::Point&, const Line3Facet::Point&,
    const std::array<Line3Facet::Point, Line3Facet::kNodes>&, const std::array<Line3Facet::Point, Line3Facet::kNodes>&, double);
extern template SweptCrossing sweptCrossing<Tri3Facet>(const Tri3Facet::Point&, const Tri3Facet::Point&,
    const std::array<Tri3Facet::Point, Tri3Facet::kNodes>&, const std::array<Tri3Facet::Point, Tri3Facet::kNodes>&, double);
extern template SweptCrossing sweptCrossing<Tri6Facet>(const Tri6Facet::Point&, const Tri6Facet::Point&,
    const std::array<Tri6Facet::Point, Tri6Facet::kNodes>&, const std::array<Tri6Facet::Point, Tri6Facet::kNodes>&, double);
extern template SweptCrossing sweptCrossing<Quad8Facet>(const Quad8Facet::Point&, const Quad8Facet::Point&,
    const std::array<Quad8Facet::Point, Quad8Facet::kNodes>&, const std::array<Quad8Facet::Point, Quad8Facet::kNodes>&, double);
extern template SweptCrossing sweptCrossing<Quad9Facet>(const Quad9Facet::Point&, const Quad9Facet::Point&,
    const std::array<Quad9Facet::Point, Quad9Facet::kNodes>&, const std::array<Quad9Facet::Point, Quad9Facet::kNodes>&, double);

}  // namespace contessa::contact
