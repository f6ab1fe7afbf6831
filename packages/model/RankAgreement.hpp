#pragma once
// What one rank alone may find (its part's conflict, its file's write error) told to every rank, so
// that all of them stop with the same one-line message and none is left waiting in a collective: the
// rule of common/RankAgreement.hpp on the model's Teuchos communicator.
#include <string>

#include "model/TpetraTypes.hpp"

namespace contessa::model {

/// Collective: the message of the lowest rank whose `message` is not empty, on every rank ("" when no
/// rank has one).
std::string firstMessageOfAnyRank(const Comm& comm, std::string message);

}  // namespace contessa::model
