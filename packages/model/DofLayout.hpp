#pragma once
// Where the unknowns live on each rank: the owned and overlapped DOF maps (node·dim + c, every component
// of a node on the node's owner), the element and node maps of the output, the Import/Export between
// owned and overlapped vectors, and the Jacobian's graph, built from the couplings the assemblers declare
// (SolidAssembler's elements, ContactAssembly's reserved contact couplings) at set-up and again when the
// contact leaves its reserved couplings (the maps never change). No physics here.
#include <cstddef>
#include <vector>

#include "mesh/DistributedMesh.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::model {

/// The couplings of this rank's overlapped rows in compressed rows: row r couples to the overlapped
/// columns columns[rowBegin[r], rowBegin[r + 1]), sorted and unique.
struct OverlapCouplings {
  std::vector<std::size_t> rowBegin;  ///< one more than the rows
  std::vector<LO> columns;

  LO numRows() const { return static_cast<LO>(rowBegin.size()) - 1; }
  std::size_t rowSize(LO r) const { return rowBegin[r + 1] - rowBegin[r]; }
  const LO* row(LO r) const { return columns.data() + rowBegin[r]; }

  /// Every element couples each of its DOFs (overlapped local, elementDofs[elementBegin[e],
  /// elementBegin[e + 1])) to all of them; `extraRows[r]` (the contact couplings, in any order, with
  /// repeats) adds to row r. Built by counting, a prefix sum and a fill, each column taken once per row.
  static OverlapCouplings gather(LO numRows, const std::vector<int>& elementDofs,
                                 const std::vector<std::size_t>& elementBegin,
                                 const std::vector<std::vector<LO>>& extraRows);
};

class DofLayout {
 public:
  /// From this rank's part of the mesh: its owned nodes, its elements and their nodes, and
  /// `replicatedNodes`, nodes every rank holds in its overlap besides its elements' nodes (contact
  /// surfaces are replicated, docs/design.md: the owner of a slave node sees its master facet wherever it
  /// slides).
  DofLayout(const Teuchos::RCP<const Comm>& comm, const mesh::DistributedMesh& part,
            const std::vector<mesh::GlobalIndex>& replicatedNodes);

  int dimension() const { return dim_; }
  const Teuchos::RCP<const Comm>& comm() const { return comm_; }
  const Teuchos::RCP<const Map>& ownedMap() const { return ownedMap_; }
  const Teuchos::RCP<const Map>& overlapMap() const { return overlapMap_; }
  const Teuchos::RCP<const Map>& elementMap() const { return elementMap_; }  ///< owned elements
  const Teuchos::RCP<const Map>& nodeMap() const { return nodeMap_; }        ///< owned nodes
  const Import& importer() const { return *importer_; }                      ///< owned → overlapped
  const Export& exporter() const { return *exporter_; }                      ///< overlapped → owned (ADD)
  /// Overlapped local index of component c of a node (invalid when the rank does not hold it).
  LO overlapDof(mesh::GlobalIndex node, int c) const { return overlapMap_->getLocalElement(node * dim_ + c); }
  LO numOverlapDofs() const { return static_cast<LO>(overlapMap_->getNodeNumElements()); }

  /// Builds the owned graph from the overlapped rows' couplings. Rows shared between ranks receive the
  /// entries of each. The graph is the one Tpetra's fillComplete makes of the same entries (its column
  /// map by Tpetra's own rule, rows sorted by local column), built here directly in compressed rows.
  /// Collective. A new graph object each time: whoever holds the old one (a Jacobian made on it, MUMPS'
  /// analysed pattern) tells them apart by identity.
  void buildGraph(const OverlapCouplings& rows);
  const Teuchos::RCP<const CrsGraph>& ownedGraph() const { return ownedGraph_; }

 private:
  /// The shared rows this rank holds but does not own, sent to their owners: per owned row, the global
  /// columns the other ranks give it (null on one rank, where no row is shared). Collective.
  Teuchos::RCP<const CrsGraph> receiveSharedRows(const OverlapCouplings& rows) const;

  Teuchos::RCP<const Comm> comm_;
  int dim_;
  Teuchos::RCP<const Map> ownedMap_, overlapMap_, elementMap_, nodeMap_;
  Teuchos::RCP<const Export> exporter_;
  Teuchos::RCP<const Import> importer_;
  Teuchos::RCP<const CrsGraph> ownedGraph_;
};

}  // namespace contessa::model
