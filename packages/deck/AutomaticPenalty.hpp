#pragma once
// Automatic penalties (issue 21, docs/theory-contact.md §5.3): with no Normal Penalty in an interface, the
// normal penalty is a factor times the stiffness of the elements under its slave facets,
//   ε_N = f · max over the slave facets of E'/h,   E' = E/(1 − ν²) (initial moduli of the element's material),
//   h = twice the distance from the element's centroid to the centroid of its slave side
// (the element's thickness under the side for a parallelogram or a brick), so that a deck in any unit
// system gives the same answer without a penalty value; with Friction Coefficient > 0, Slip Tolerance = 0
// and no Tangential Penalty, ε_T = ε_N.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "contact/InterfaceSpec.hpp"
#include "deck/ProblemDefinition.hpp"

namespace contessa::deck {

/// E' = E/(1 − ν²) of a material, from its tangent at F = I (λ = A_xxyy, μ = A_xyxy: E' = 4μ(λ + μ)/(λ + 2μ)).
double planeStrainModulus(const mechanics::Material& material);

/// Collective: the largest E'/h over the facets of side set `sideSet` (every rank's part).
double largestStiffnessOverSize(const mesh::DistributedMesh& mesh, const std::vector<BlockPhysics>& blocks,
                                const std::string& sideSet);

/// Collective: with Enforcement = Augmented Lagrangian and a Normal Penalty below E'/h/10 of its slave side,
/// rank 0 warns in one line: the Uzawa updates then converge by ε/(ε + E'/h) only (docs/theory-contact.md
/// §15, "A penalty too soft").
void warnSoftAugmentedPenalty(const contact::ContactInterfaceSpec& spec, const Teuchos::ParameterList& list,
                              const mesh::DistributedMesh& mesh, const std::vector<BlockPhysics>& blocks);

/// Collective: fills the automatic penalties of an interface's passes (`list`: its deck sublist; the
/// second pass's slave side is the Master Side Set); warns of a soft augmented one that is given.
void setAutomaticPenalties(std::vector<contact::ContactInterfaceSpec>& passes, const Teuchos::ParameterList& list,
                           const mesh::DistributedMesh& mesh, const std::vector<BlockPhysics>& blocks);

}  // namespace contessa::deck
