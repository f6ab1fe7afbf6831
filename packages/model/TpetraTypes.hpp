#pragma once
// The Tpetra types of this Trilinos build (double, int, long long; Kokkos Serial).
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace contessa::model {

using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;
using Vector = Tpetra::Vector<double, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<double, LO, GO, Node>;
using CrsGraph = Tpetra::CrsGraph<LO, GO, Node>;
using CrsMatrix = Tpetra::CrsMatrix<double, LO, GO, Node>;
using Operator = Tpetra::Operator<double, LO, GO, Node>;
using Import = Tpetra::Import<LO, GO, Node>;
using Export = Tpetra::Export<LO, GO, Node>;
using Comm = Teuchos::Comm<int>;

}  // namespace contessa::model
