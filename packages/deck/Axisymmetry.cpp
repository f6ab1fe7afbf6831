#include "deck/Axisymmetry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <mpi.h>

#include "common/Error.hpp"
#include "common/RankAgreement.hpp"

namespace contessa::deck {

bool axisymmetricProblem(const std::vector<BlockPhysics>& blocks, const mesh::DistributedMesh& part) {
  if (blocks.empty()) return false;
  const bool revolved = blocks.front().element->axisymmetric();
  for (const auto& b : blocks)
    requireInput(b.element->axisymmetric() == revolved,
                 "Problem/Blocks/" + b.block + "/Element: '" + b.elementName + "' is " +
                     (revolved ? "not " : "") + "axisymmetric but block '" + blocks.front().block + "' uses '" +
                     blocks.front().elementName + "': every block of a model must be axisymmetric, or none");
  if (!revolved) return false;
  // The axis is x = 0: a node at x < 0 lies on its far side (this rank's part; every rank agrees). A
  // node meant to lie on the axis may sit a round-off away from it (cos 270° = −1.8e-16): tolerated up
  // to 1e-12 of the part's extent.
  const mesh::Mesh& mesh = part.local();
  double extent = 0.0;
  for (double c : mesh.coordinates) extent = std::max(extent, std::fabs(c));
  std::string message;
  for (std::size_t n = 0; n < mesh.coordinates.size() / 2 && message.empty(); ++n)
    if (mesh.coordinates[2 * n] < -1e-12 * extent) {
      std::ostringstream text;
      text << "Problem/Mesh: node " << part.part.globalNodes[n] + 1 << " lies at x = " << mesh.coordinates[2 * n]
           << " < 0; an axisymmetric mesh lies in x >= 0 (x is the radius, the y axis the axis of revolution)";
      message = text.str();
    }
  const RankMessage agreed = lowestSpeakingRank(part.comm, message.empty() ? 0 : 1, message);
  if (agreed.spoken()) throw InputError(agreed.message);
  return true;
}

}  // namespace contessa::deck
