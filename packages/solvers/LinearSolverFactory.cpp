#include "solvers/LinearSolverFactory.hpp"

#include <array>

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <MueLu_MasterList.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Ifpack2_Parameters.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_MueLuPreconditionerFactory.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "common/Error.hpp"
#include "common/ErrorText.hpp"
#include "mesh/DistributedMesh.hpp"
#include "solvers/IterativeSolveMonitor.hpp"
#include "solvers/MumpsSolver.hpp"
#include "solvers/PreconditionerReuse.hpp"
#include "solvers/RigidBodyModes.hpp"

namespace contessa::solvers {
namespace {

void registerSolvers(Stratimikos::DefaultLinearSolverBuilder& builder) {
  builder.setLinearSolveStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::LinearOpWithSolveFactoryBase<double>, MumpsLinearOpWithSolveFactory>(),
      "MUMPS");
  builder.setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>,
                                  Thyra::Ifpack2PreconditionerFactory<model::CrsMatrix>>(),
      "Ifpack2");
  // MueLu over Contessa's Tpetra types (double, int, long long, Serial): smoothed aggregation AMG.
  Stratimikos::enableMueLu<model::LO, model::GO, model::Node>(builder, "MueLu");
}

// A text value of parameter `name` converted to the type of `expected` (int, double or bool; other types
// are left as they are); a value that does not convert is an InputError naming the parameter.
void typeTextParameter(Teuchos::ParameterList& list, const std::string& name, const Teuchos::ParameterEntry& expected,
                       const std::string& where) {
  if (!list.isType<std::string>(name)) return;
  const std::string text = list.get<std::string>(name);
  std::size_t used = 0;
  bool ok = false;
  try {
    if (expected.isType<int>()) {
      const int value = std::stoi(text, &used);
      ok = used == text.size();
      if (ok) list.set(name, value);
    } else if (expected.isType<double>()) {
      const double value = std::stod(text, &used);
      ok = used == text.size();
      if (ok) list.set(name, value);
    } else if (expected.isType<bool>()) {
      ok = text == "true" || text == "false";
      if (ok) list.set(name, text == "true");
    } else {
      return;
    }
  } catch (const std::exception&) {
  }
  if (!ok) throw InputError(where + "/" + name + ": expected " + expected.getAny(false).typeName() + ", got '" + text + "'");
}

// The sublists MueLu hands to Ifpack2 (its smoothers and a relaxation or Chebyshev coarse solver): their
// values given by --set are typed by Ifpack2's own list of parameters. A name Ifpack2 does not know is left
// for the smoother to judge (a coarse direct solver's parameters are Amesos2's).
void typeIfpack2Parameters(Teuchos::ParameterList& list, const std::string& where) {
  static const Teuchos::ParameterList valid = [] {
    Teuchos::ParameterList all;
    Ifpack2::getValidParameters(all);
    return all;
  }();
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = list.name(it);
    if (!list.isSublist(name) && valid.isParameter(name)) typeTextParameter(list, name, valid.getEntry(name), where);
  }
}

// MueLu does not type its parameters for Stratimikos: a value given by --set arrives as text. Each
// text value of a parameter MueLu knows as a number or a flag is converted to that type (MueLu's own
// list of parameters), and likewise inside the smoother and coarse-solver sublists by Ifpack2's list; a
// value that does not convert is an InputError naming the parameter.
void typeMueLuParameters(Teuchos::ParameterList& list, const std::string& where) {
  static const std::array<const char*, 4> kIfpack2Sublists = {"smoother: params", "smoother: pre params",
                                                              "smoother: post params", "coarse: params"};
  const auto master = MueLu::MasterList::List();
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = list.name(it);
    if (list.isSublist(name)) {  // "level 1", "repartition: params", ...: MueLu checks them
      for (const char* sublist : kIfpack2Sublists)
        if (name == sublist) typeIfpack2Parameters(list.sublist(name), where + "/" + name);
      continue;
    }
    if (!master->isParameter(name))
      throw InputError(where + "/" + name + ": not a MueLu parameter (MueLu's user guide lists them, e.g. 'smoother: type', "
                       "'coarse: max size', 'aggregation: drop tol')");
    typeTextParameter(list, name, master->getEntry(name), where);
  }
}

// On more than one rank MueLu's coarsest matrix is gathered onto one rank (a repartition of the coarse
// levels), so that its direct solve, Amesos2 KLU2, runs on one rank: distributed over two it does not
// solve the coarse problem exactly in this Trilinos build (docs/architecture.md refuses Amesos2 as a
// solver on more than one rank), and the Krylov iterations per solve doubled on the 3D punch at 1.5·10^4
// unknowns (16.3 against 8.0 on one rank; 7.6 with the repartition, bench/README.md, "Issue 23, fourth
// round"). MueLu's heuristic moves a level onto fewer ranks when it has fewer than `repartition: min rows
// per proc` rows per rank; set to the coarse size limit, only the levels that small move, the coarsest
// onto one rank. ParMETIS (through Zoltan2) partitions a level that must be split anew; it needs no
// coordinates, which MueLu's default geometric partitioner would. What the deck sets is kept.
void completeCoarseRepartition(Teuchos::ParameterList& muelu) {
  if (muelu.isParameter("repartition: enable")) return;
  const auto master = MueLu::MasterList::List();
  const int coarseSize = muelu.isType<int>("coarse: max size") ? muelu.get<int>("coarse: max size")
                                                                : master->get<int>("coarse: max size");
  muelu.set("repartition: enable", true);
  if (!muelu.isParameter("repartition: start level")) muelu.set("repartition: start level", 1);
  if (!muelu.isParameter("repartition: min rows per proc")) muelu.set("repartition: min rows per proc", coarseSize);
  if (!muelu.isSublist("repartition: params") && !muelu.isParameter("repartition: partitioner"))
    muelu.sublist("repartition: params").set("algorithm", std::string("parmetis"));
}

// MueLu's default smoother is one sweep of symmetric Gauss-Seidel before and after the coarse correction;
// Contessa's preconditioner serves GMRES, which needs no symmetric one, and a forward Gauss-Seidel sweep
// costs half a symmetric one: on the 3D punch it needs 1.4 to 1.5 times the Krylov iterations and 19 to
// 22 % less CPU per run from 3.8·10^4 to 1.1·10^5 unknowns (5 % at 1.1·10^4; bench/README.md, "Issue 23,
// fifth round"). The smoother the deck gives is kept, and completed where MueLu would not: a "smoother:
// params" with no "relaxation: type" is handed to Ifpack2 as it is, whose relaxation then defaults to
// undamped Jacobi (the cube of the iterative tests stalls at a relative residual of 0.999 with "relaxation:
// sweeps = 2" alone). There the relaxation is the one the deck would have had without the sublist:
// Contessa's forward Gauss-Seidel when no "smoother: type" is given, MueLu's symmetric one under
// "smoother: type = RELAXATION" (what MueLu itself takes when that type comes without parameters).
void completeSmoother(Teuchos::ParameterList& muelu) {
  for (auto it = muelu.begin(); it != muelu.end(); ++it) {
    const std::string name = muelu.name(it);
    if (name.rfind("smoother:", 0) == 0 && name != "smoother: type" && name != "smoother: params") return;
  }
  const bool typed = muelu.isParameter("smoother: type");
  if (typed && !(muelu.isType<std::string>("smoother: type") && muelu.get<std::string>("smoother: type") == "RELAXATION"))
    return;
  if (typed && !muelu.isSublist("smoother: params")) return;  // MueLu's symmetric Gauss-Seidel
  auto& params = muelu.sublist("smoother: params");
  if (params.isParameter("relaxation: type")) {
    if (!typed) muelu.set("smoother: type", std::string("RELAXATION"));
    return;
  }
  params.set("relaxation: type", std::string(typed ? "Symmetric Gauss-Seidel" : "Gauss-Seidel"));
  muelu.set("smoother: type", std::string("RELAXATION"));
}

using MueLuFactory = Thyra::MueLuPreconditionerFactory<double, model::LO, model::GO, model::Node>;

// The first line of a library's message that says something (Teuchos prefixes file and line, and
// MueLu and Belos add pages of context).
std::string firstMeaningfulLine(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size() && lines.size() < 2) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line = text.substr(start, end - start);
    start = end + 1;
    line.erase(0, line.find_first_not_of(" \t"));
    if (line.empty() || line.rfind("/", 0) == 0 || line.find(".hpp:") != std::string::npos ||
        line.find(".cpp:") != std::string::npos || line.rfind("Throw number", 0) == 0 || line.rfind("Throw test", 0) == 0)
      continue;
    // A line that announces more ("Could not construct any smoother:") takes the next one along.
    if (!lines.empty() || line.back() == ':') lines.push_back(line);
    else return line.size() > 300 ? line.substr(0, 300) + "..." : line;
  }
  std::string joined;
  for (const auto& l : lines) joined += (joined.empty() ? "" : " ") + l;
  if (joined.size() > 300) joined = joined.substr(0, 300) + "...";
  return joined.empty() ? plainMessage(std::runtime_error(text)) : joined;
}

// Builds and applies the deck's iterative solver once, on a small diagonally dominant matrix (a
// tridiagonal stiffness, 60 rows per rank so that 2 or 3 DOFs per node divide it), so that every
// parameter of Belos, Ifpack2 and MueLu is read before the run rather than at its first solve.
// Whether the probe converges does not matter; an exception does. The rows outnumber the iterations the
// solve needs (about 15): a Krylov space exhausted before the tolerance is met is a breakdown that Belos'
// GMRES reports as NaN implicit residuals whenever Num Blocks is given (6 rows did that).
void probeIterativeSolver(Thyra::LinearOpWithSolveFactoryBase<double>& factory,
                          const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  const model::LO local = 60;
  auto map = Teuchos::rcp(new model::Map(static_cast<Tpetra::global_size_t>(local * comm->getSize()), local, 0, comm));
  auto A = Teuchos::rcp(new model::CrsMatrix(map, 3));
  const model::GO n = static_cast<model::GO>(map->getGlobalNumElements());
  for (model::LO i = 0; i < local; ++i) {
    const model::GO row = map->getGlobalElement(i);
    std::vector<model::GO> cols;
    std::vector<double> vals;
    if (row > 0) cols.push_back(row - 1), vals.push_back(-1.0);
    cols.push_back(row), vals.push_back(4.0);
    if (row + 1 < n) cols.push_back(row + 1), vals.push_back(-1.0);
    A->insertGlobalValues(row, Teuchos::ArrayView<const model::GO>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const model::Operator>(A));
  auto lows = Thyra::linearOpWithSolve(factory, op);
  model::Vector b(map), x(map);
  b.putScalar(1.0);
  auto tb = Thyra::createConstVector(Teuchos::rcpFromRef(b).getConst());
  auto tx = Thyra::createVector(Teuchos::rcpFromRef(x));
  lows->solve(Thyra::NOTRANS, *tb, tx.ptr());
}

// The Belos solver's Convergence Tolerance and Maximum Iterations as it uses them: the deck's, else
// Belos' defaults (from the factory's lists once Stratimikos has given it the deck's).
IterativeSolveLimits belosLimits(const Thyra::LinearOpWithSolveFactoryBase<double>& factory) {
  IterativeSolveLimits limits{1e-8, 1000};
  const auto given = factory.getParameterList();
  const auto valid = factory.getValidParameters();
  std::string type = "Pseudo Block GMRES";
  if (!given.is_null() && given->isType<std::string>("Solver Type")) type = given->get<std::string>("Solver Type");
  for (const auto& list : {valid, given}) {
    if (list.is_null() || !list->isSublist("Solver Types") || !list->sublist("Solver Types").isSublist(type)) continue;
    const auto& solver = list->sublist("Solver Types").sublist(type);
    if (solver.isType<double>("Convergence Tolerance")) limits.tolerance = solver.get<double>("Convergence Tolerance");
    if (solver.isType<int>("Maximum Iterations")) limits.maxIterations = solver.get<int>("Maximum Iterations");
  }
  return limits;
}

// "Belos (Pseudo Block GMRES) with MueLu", for messages.
std::string iterativeSolverName(const Teuchos::ParameterList& stratimikos) {
  std::string belos = "Pseudo Block GMRES";
  if (stratimikos.isSublist("Linear Solver Types") && stratimikos.sublist("Linear Solver Types").isSublist("Belos")) {
    const auto& list = stratimikos.sublist("Linear Solver Types").sublist("Belos");
    if (list.isType<std::string>("Solver Type")) belos = list.get<std::string>("Solver Type");
  }
  const std::string prec = stratimikos.isType<std::string>("Preconditioner Type") ? stratimikos.get<std::string>("Preconditioner Type") : std::string("None");
  return "Belos " + belos + (prec == "None" ? std::string(" without preconditioner") : " with " + prec);
}

std::string joinNames(const Teuchos::ParameterList& list) {
  std::string out;
  for (auto it = list.begin(); it != list.end(); ++it) out += (out.empty() ? "" : ", ") + list.name(it);
  return out;
}

// Stratimikos reports a refused list with pages of Teuchos text. After it refuses, this finds the
// first entry of the deck that its valid list does not take and says why in one line naming the deck
// path; empty when it finds none.
std::string firstRefusedEntry(const Teuchos::ParameterList& given, const Teuchos::ParameterList& valid,
                              const std::string& path) {
  for (auto it = given.begin(); it != given.end(); ++it) {
    const std::string& name = given.name(it);
    const std::string where = path + "/" + name;
    const Teuchos::ParameterEntry& entry = given.entry(it);
    const Teuchos::ParameterEntry* expected = valid.getEntryPtr(name);
    if (expected == nullptr) return where + ": unknown parameter (expected one of: " + joinNames(valid) + ")";
    if (entry.isList() != expected->isList())
      return where + (expected->isList() ? ": expected a sublist" : ": expected a parameter, not a sublist");
    if (entry.isList()) {
      const std::string inner = firstRefusedEntry(given.sublist(name), valid.sublist(name), where);
      if (!inner.empty()) return inner;
      continue;
    }
    const auto validator = expected->validator();
    if (validator.is_null()) {
      if (entry.getAny(false).type() != expected->getAny(false).type())
        return where + ": expected type " + expected->getAny(false).typeName() + ", got " + entry.getAny(false).typeName();
      continue;
    }
    // A boolean given as text (--set of a parameter the deck does not hold) must read true or false.
    if (dynamic_cast<const Teuchos::BoolParameterEntryValidator*>(validator.get()) != nullptr && entry.isType<std::string>()) {
      const std::string value = Teuchos::getValue<std::string>(entry);
      if (value != "true" && value != "false") return where + ": expected true or false; got '" + value + "'";
      continue;
    }
    const auto strings = validator->validStringValues();
    if (!strings.is_null() && entry.isType<std::string>()) {
      const std::string value = Teuchos::getValue<std::string>(entry);
      std::string allowed;
      bool found = false;
      for (const auto& s : *strings) {
        allowed += (allowed.empty() ? "" : ", ") + s;
        found = found || s == value;
      }
      if (!found) return where + ": expected one of " + allowed + "; got '" + value + "'";
    }
    try {
      validator->validate(entry, name, path);
    } catch (const std::exception& e) {
      return where + ": " + plainMessage(e);
    }
  }
  return "";
}

// The Belos solver's own sublist, completed where Stratimikos 13.2 or Belos' defaults do not serve:
// - Convergence Tolerance: once the solver's sublist exists (any parameter given in it, e.g. Num Blocks),
//   Thyra's BelosLinearOpWithSolve takes its default tolerance only from there and otherwise solves to a
//   tolerance of −1, which never converges; Belos' own default 1e-8 is set when absent.
// - Num Blocks (GMRES): the whole Krylov basis (Num Blocks + 1 vectors) is allocated at the first solve.
//   Belos' default of 300 is 2.4 KB per unknown, a quarter of a 3D contact run's memory, while Contessa's
//   solves take 10–30 iterations with MueLu; without a deck value the restart length is kGmresRestart.
// Both documented in docs/user-guide.md (Iterative solvers).
constexpr double kBelosTolerance = 1e-8;
constexpr int kGmresRestart = 50;

void completeBelosSolverList(Teuchos::ParameterList& stratimikos) {
  if (!stratimikos.isType<std::string>("Linear Solver Type") || stratimikos.get<std::string>("Linear Solver Type") != "Belos")
    return;
  auto& belos = stratimikos.sublist("Linear Solver Types").sublist("Belos");
  const std::string type = belos.isType<std::string>("Solver Type") ? belos.get<std::string>("Solver Type") : "Pseudo Block GMRES";
  auto& solver = belos.sublist("Solver Types").sublist(type);
  if (!solver.isParameter("Convergence Tolerance")) solver.set("Convergence Tolerance", kBelosTolerance);
  if ((type == "Pseudo Block GMRES" || type == "Block GMRES") && !solver.isParameter("Num Blocks"))
    solver.set("Num Blocks", kGmresRestart);
}

}  // namespace

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolverFactory(
    Teuchos::ParameterList& stratimikos, const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerSolvers(builder);
  try {
    // The solvers keep pointers into the list: give them their own copy.
    auto own = Teuchos::rcp(new Teuchos::ParameterList(stratimikos));
    bool chooseReuseType = false;
    // MueLu prints its hierarchy at every setup unless told not to: quiet unless the deck asks.
    if (own->isType<std::string>("Preconditioner Type") && own->get<std::string>("Preconditioner Type") == "MueLu") {
      auto& muelu = own->sublist("Preconditioner Types").sublist("MueLu");
      if (!muelu.isParameter("verbosity")) muelu.set("verbosity", std::string("none"));
      typeMueLuParameters(muelu, "Piro/Stratimikos/Preconditioner Types/MueLu");
      // The aggregation once per matrix graph, not once per Newton iteration; without the deck's
      // "reuse: type" the reuse wrapper chooses it per hierarchy (PreconditionerReuse.hpp).
      chooseReuseType = !muelu.isParameter("reuse: type");
      if (chooseReuseType) muelu.set("reuse: type", std::string(kMueLuReuseType));
      if (comm->getSize() > 1) completeCoarseRepartition(muelu);
      completeSmoother(muelu);
    }
    completeBelosSolverList(*own);
    builder.setParameterList(own);
    // Stratimikos hands a solver its sublist only at the first solve: check MUMPS' now, before the run.
    if (stratimikos.isSublist("Linear Solver Types") && stratimikos.sublist("Linear Solver Types").isSublist("MUMPS")) {
      Teuchos::ParameterList mumps(stratimikos.sublist("Linear Solver Types").sublist("MUMPS"));
      const auto valid = MumpsLinearOpWithSolveFactory().getValidParameters();
      // Twice: the first pass turns a number given as text (--set) into a number, the second checks its range.
      mumps.validateParametersAndSetDefaults(*valid);
      mumps.validateParametersAndSetDefaults(*valid);
    }
    auto factory = Thyra::createLinearSolveStrategy(builder);
    if (!stratimikos.isType<std::string>("Linear Solver Type") || stratimikos.get<std::string>("Linear Solver Type") != "Belos")
      return factory;
    // MueLu's hierarchy kept while the matrix graph is (the deck's "reuse: type" says how much of it).
    if (auto muelu = Teuchos::rcp_dynamic_cast<MueLuFactory>(factory->getPreconditionerFactory()); !muelu.is_null())
      factory->setPreconditionerFactory(Teuchos::rcp(new GraphKeyedPreconditionerFactory(muelu, chooseReuseType)), "MueLu");
    try {
      probeIterativeSolver(*factory, comm);
    } catch (const std::exception& e) {
      throw InputError("Piro/Stratimikos (" + iterativeSolverName(stratimikos) +
                       "): the solver refused its parameters: " + firstMeaningfulLine(e.what()));
    }
    return monitorIterativeSolver(factory, iterativeSolverName(stratimikos), belosLimits(*factory));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    const std::string refused = firstRefusedEntry(stratimikos, *builder.getValidParameters(), "Piro/Stratimikos");
    throw InputError(refused.empty() ? "Piro/Stratimikos: " + plainMessage(e) : refused);
  }
}

void provideNearNullSpace(Thyra::LinearOpWithSolveFactoryBase<double>& factory, const model::Map& ownedDofMap,
                          const mesh::DistributedMesh& part) {
  auto precFactory = unmonitored(factory.getPreconditionerFactory());
  if (auto keyed = Teuchos::rcp_dynamic_cast<GraphKeyedPreconditionerFactory>(precFactory); !keyed.is_null())
    precFactory = keyed->inner();
  auto muelu = Teuchos::rcp_dynamic_cast<MueLuFactory>(precFactory);
  if (muelu.is_null()) return;
  const mesh::Mesh& local = part.local();
  const int dim = local.dimension;
  // The centroid of the whole mesh, the same on every rank: the sum over every rank's owned nodes.
  std::array<double, 4> sum{}, total{};  // Σx, Σy, Σz, count
  for (std::size_t n = 0; n < part.nodeOwner.size(); ++n) {
    if (part.nodeOwner[n] != part.rank) continue;
    for (int k = 0; k < dim; ++k) sum[k] += local.coordinates[n * dim + k];
    sum[3] += 1.0;
  }
  Teuchos::reduceAll(*ownedDofMap.getComm(), Teuchos::REDUCE_SUM, 4, sum.data(), total.data());
  std::array<double, 3> center{};
  for (int k = 0; k < dim; ++k) center[k] = total[3] > 0 ? total[k] / total[3] : 0.0;
  const int modes = rigidBodyModeCount(dim);
  auto nullspace = Teuchos::rcp(new model::MultiVector(Teuchos::rcpFromRef(ownedDofMap), modes));
  std::vector<double> nodeCoordinates(dim);
  for (std::size_t i = 0; i < ownedDofMap.getNodeNumElements(); ++i) {
    const model::GO dof = ownedDofMap.getGlobalElement(static_cast<model::LO>(i));
    const model::GO node = dof / dim;
    const int component = static_cast<int>(dof % dim);
    const auto localNode = static_cast<std::size_t>(part.localNode(node));
    for (int k = 0; k < dim; ++k) nodeCoordinates[k] = local.coordinates[localNode * dim + k];
    const auto nodeModes = rigidBodyModes(dim, nodeCoordinates, center);
    for (int m = 0; m < modes; ++m)
      nullspace->replaceLocalValue(static_cast<model::LO>(i), m, nodeModes[static_cast<std::size_t>(m * dim + component)]);
  }
  auto params = muelu->getNonconstParameterList();
  if (params.is_null()) {
    params = Teuchos::rcp(new Teuchos::ParameterList("MueLu"));
    muelu->setParameterList(params);
  }
  if (!params->isParameter("number of equations")) params->set("number of equations", dim);
  params->set("Nullspace", nullspace);
}

Teuchos::RCP<const Teuchos::ParameterList> stratimikosValidParameters() {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerSolvers(builder);
  return builder.getValidParameters();
}

}  // namespace contessa::solvers
