#pragma once
// The one rule for what one rank alone may find (its file missing, its part's conflict, its write
// error): the lowest rank that has something to say speaks for all, so that every rank stops with the
// same one-line message and none is left waiting in a collective call. mesh::throwIfAnyRankFailed,
// model::firstMessageOfAnyRank and app::agreeOnInput are this rule with their own exception types.
#include <string>

#include <mpi.h>

namespace contessa {

/// What the lowest speaking rank said.
struct RankMessage {
  int rank = -1;    ///< the lowest rank with a status other than 0; −1 when no rank spoke
  int status = 0;   ///< its status (the caller's code: what kind of failure)
  std::string message;
  bool spoken() const { return rank >= 0; }
};

/// Collective over `comm`: each rank gives a status (0: nothing to say) and a message; every rank returns
/// the lowest speaking rank's. On one rank, or before MPI is initialised, a rank's own.
RankMessage lowestSpeakingRank(MPI_Comm comm, int status, std::string message);

}  // namespace contessa
