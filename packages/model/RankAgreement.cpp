#include "model/RankAgreement.hpp"

#include <utility>

#include "common/MpiCommOf.hpp"
#include "common/RankAgreement.hpp"

namespace contessa::model {

std::string firstMessageOfAnyRank(const Comm& comm, std::string message) {
  const int status = message.empty() ? 0 : 1;
  return lowestSpeakingRank(mpiCommOf(comm), status, std::move(message)).message;
}

}  // namespace contessa::model
