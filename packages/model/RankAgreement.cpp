#include "model/RankAgreement.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace contessa::model {

std::string firstMessageOfAnyRank(const Comm& comm, std::string message) {
  const int mine = message.empty() ? comm.getSize() : comm.getRank();
  int first = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &mine, &first);
  if (first == comm.getSize()) return "";
  int size = static_cast<int>(message.size());
  Teuchos::broadcast(comm, first, &size);
  message.resize(static_cast<std::size_t>(size));
  Teuchos::broadcast(comm, first, size, message.data());
  return message;
}

}  // namespace contessa::model
