#include "solvers/MumpsInput.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace contessa::solvers {

bool MumpsDistributedInput::update(const model::CrsMatrix& A, MPI_Comm comm) {
  const auto graph = A.getCrsGraph();
  int newPatternHere = graph.get() != graph_.get() ? 1 : 0, newPattern = 0;
  MPI_Allreduce(&newPatternHere, &newPattern, 1, MPI_INT, MPI_MAX, comm);
  const auto local = A.getLocalMatrixHost();
  if (newPatternHere) {
    TEUCHOS_TEST_FOR_EXCEPTION(A.getGlobalNumRows() > static_cast<Tpetra::global_size_t>(std::numeric_limits<MUMPS_INT>::max()),
                               std::runtime_error, "MUMPS input: too many rows for MUMPS' 32-bit indices");
    graph_ = graph;
    n_ = static_cast<MUMPS_INT>(A.getGlobalNumRows());
    const auto& rowMap = *A.getRowMap();
    const auto& colMap = *A.getColMap();
    const auto& rowBegin = local.graph.row_map;
    const auto& entries = local.graph.entries;
    rows_.resize(entries.extent(0));
    cols_.resize(entries.extent(0));
    for (std::size_t r = 0; r + 1 < rowBegin.extent(0); ++r) {
      const auto row = static_cast<MUMPS_INT>(rowMap.getGlobalElement(static_cast<model::LO>(r)) + 1);
      for (std::size_t k = rowBegin(r); k < rowBegin(r + 1); ++k) {
        rows_[k] = row;
        cols_[k] = static_cast<MUMPS_INT>(colMap.getGlobalElement(entries(k)) + 1);
      }
    }
  }
  values_.assign(local.values.data(), local.values.data() + local.values.extent(0));
  return newPattern != 0;
}

}  // namespace contessa::solvers
