#pragma once
// Sums element and contact stiffness blocks straight into the value array of the Jacobian, at positions
// computed once per graph: one scatter serves one graph (a rebuild of the graph makes a new scatter), so a
// block's entries always land in the same places.
//
// Rows this rank owns go into a value array laid out exactly as the Jacobian's (its graph is
// `ownedGraph`); the few overlapped rows owned by another rank (shared element nodes, contact
// surfaces) go into a small "ghost" matrix that is exported (ADD) to its owners, with an Export plan
// built once. On one rank there are no ghost rows and no communication at all. The Jacobian itself
// is filled once (fillComplete) and from then on only its values change: no resumeFill, no
// fillComplete, no global-index lookup per entry.
#include <array>
#include <unordered_map>
#include <vector>

#include "model/DofLayout.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::model {

class StiffnessScatter {
 public:
  /// `overlapRows.row(r)`: the columns (overlapped local DOFs) of overlapped row r; the rows this rank
  /// owns must be in `ownedGraph` (fill complete, sorted), the others become ghost rows.
  StiffnessScatter(const Teuchos::RCP<const CrsGraph>& ownedGraph, const Teuchos::RCP<const Map>& overlapMap,
                   const OverlapCouplings& overlapRows);

  /// Set-up: records an element's DOFs (overlapped local numbering), in the order the element loop
  /// visits the elements, and computes where its n × n block goes.
  void addElement(const int* dofs, int n);

  /// Start of an assembly pass: every value is set to zero.
  void beginPass();
  /// Adds an element's stiffness (n × n, row-major). Elements come in the order of addElement(); one
  /// skipped (a failed element) is recognised by its DOFs, and an unknown DOF list is looked up.
  void addElementStiffness(const int* dofs, int n, const double* ke);
  /// Adds any block (contact couplings). Its positions are cached per first DOF: a coupling that is
  /// the same as at the previous call for that DOF costs no lookup.
  void addStiffness(const LO* dofs, int n, const double* k);

  /// Copies the assembled values into `W` (whose graph must be `ownedGraph`), adds the ghost rows of
  /// the other ranks to it (collective on several ranks), and makes `identityRows` (owned local rows)
  /// rows of the identity. Fills `W` the first time; never again (a rebuilt graph gets a new W).
  void copyTo(CrsMatrix& W, const std::vector<LO>& identityRows) const;

  /// Position of entry (row, col) (overlapped local DOFs) in the value arrays: ≥ 0 in the owned
  /// values, < 0 in the ghost values (−1 − index). Throws std::logic_error when the graph lacks it.
  int position(LO row, LO col) const;

 private:
  void add(const int* positions, int count, const double* values);

  Teuchos::RCP<const CrsGraph> ownedGraph_;
  Teuchos::RCP<const Map> overlapMap_;
  // Owned rows: overlapped row → local row of the owned graph (−1 if a ghost row), overlapped
  // column → local column of the owned graph (−1 if absent); CSR of the owned graph.
  std::vector<LO> ownedRow_, ownedCol_;
  std::vector<std::size_t> rowBegin_;
  std::vector<LO> columns_;
  std::vector<double> values_;
  // Ghost rows: overlapped row → local row of the ghost matrix; its CSR (columns: overlapped DOFs).
  std::vector<LO> ghostRow_;
  std::vector<std::size_t> ghostRowBegin_;
  std::vector<LO> ghostColumns_;
  Teuchos::RCP<CrsMatrix> ghostMatrix_;
  Teuchos::RCP<const Export> ghostExporter_;
  bool distributed_ = false;

  double* ghostValues_ = nullptr;  // the ghost matrix's values during a pass

  // Elements: DOFs (n each) and positions (n² each), flattened; elements by first DOF (to recognise
  // one out of order); the element loop's cursor.
  std::vector<std::size_t> elementDofBegin_, elementPositionBegin_;
  std::vector<int> elementDofs_, elementPositions_, elementSize_;
  std::unordered_multimap<int, std::size_t> elementsByFirstDof_;
  std::size_t cursor_ = 0;

  // Couplings seen before, by first DOF.
  struct CachedBlock {
    std::vector<LO> dofs;
    std::vector<int> positions;
  };
  std::unordered_map<LO, CachedBlock> blocks_;
  std::vector<int> scratch_;
  std::vector<int> columnOrder_;  // addElement's columns by local column
};

}  // namespace contessa::model
