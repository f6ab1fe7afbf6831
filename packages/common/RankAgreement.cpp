#include "common/RankAgreement.hpp"

#include <utility>

namespace contessa {

RankMessage lowestSpeakingRank(MPI_Comm comm, int status, std::string message) {
  int initialised = 0, finalised = 0, rank = 0, size = 1;
  MPI_Initialized(&initialised);
  if (initialised) MPI_Finalized(&finalised);
  if (initialised && !finalised) {
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
  }
  RankMessage lowest;
  if (size == 1) {  // nobody to tell
    if (status != 0) lowest = {rank, status, std::move(message)};
    return lowest;
  }
  int speaker = status != 0 ? rank : size;
  MPI_Allreduce(MPI_IN_PLACE, &speaker, 1, MPI_INT, MPI_MIN, comm);
  if (speaker == size) return lowest;
  int header[2] = {status, static_cast<int>(message.size())};
  MPI_Bcast(header, 2, MPI_INT, speaker, comm);
  message.resize(static_cast<std::size_t>(header[1]));
  if (header[1] > 0) MPI_Bcast(message.data(), header[1], MPI_CHAR, speaker, comm);
  lowest = {speaker, header[0], std::move(message)};
  return lowest;
}

}  // namespace contessa
