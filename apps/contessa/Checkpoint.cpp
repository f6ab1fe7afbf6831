#include "Checkpoint.hpp"

#include <csignal>
#include <initializer_list>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <fstream>
#include <sstream>

#include <mpi.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include "ProcessEnvironment.hpp"
#include "StopSignals.hpp"
#include "common/Error.hpp"

namespace contessa::app {

namespace {

// Run-control parameters: a restarted run may change them.
bool runControl(const std::string& path) {
  for (const char* prefix : {"Problem/Title", "Problem/Output/Checkpoint/", "Problem/Regression/",
                             "Piro/LOCA/Stepper/Max Steps", "Piro/NOX/Printing/"})
    if (path.rfind(prefix, 0) == 0) return true;
  return false;
}

void flatten(const Teuchos::ParameterList& list, const std::string& prefix, std::ostringstream& out) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string path = prefix + list.name(it);
    const auto& entry = list.entry(it);
    if (entry.isList()) {
      flatten(Teuchos::getValue<Teuchos::ParameterList>(entry), path + "/", out);
    } else if (!runControl(path)) {
      std::ostringstream value;
      value.precision(17);
      value << entry.getAny(false);
      out << path << " = " << value.str() << "\n";
    }
  }
}

std::string signalName(int signal) {
  switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGUSR1: return "SIGUSR1";
    case SIGINT: return "SIGINT";
    default: return "signal " + std::to_string(signal);
  }
}

std::string shortSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", s);
  return text;
}

// "2026-11-27 01:23:45" (local time) of a time point, for the log.
std::string clockTime(std::chrono::system_clock::time_point t) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(t);
  std::tm local{};
  localtime_r(&seconds, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &local);
  return text;
}

}  // namespace

std::string resolveRestart(const Teuchos::Comm<int>& comm, const std::string& restart, const std::string& deck,
                           const std::string& outputDirectory, bool verbose) {
  if (restart != "auto") return restart;
  const std::string path = outputDirectory + "/" + std::filesystem::path(deck).stem().string() + ".restart";
  int found = 0;
  if (comm.getRank() == 0) {
    std::error_code ec;
    found = std::filesystem::is_regular_file(path, ec) ? 1 : 0;
  }
  Teuchos::broadcast(comm, 0, &found);
  if (comm.getRank() == 0 && verbose) {
    if (found) std::printf("contessa: --restart auto: continuing from %s\n", path.c_str());
    else std::printf("contessa: --restart auto: no restart file %s: a new run\n", path.c_str());
    std::fflush(stdout);
  }
  return found ? path : std::string();
}

std::string restartDeckText(const Teuchos::ParameterList& deck) {
  std::ostringstream out;
  flatten(deck, "", out);
  return out.str();
}

io::RestartContent restartIdentity(const Teuchos::ParameterList& deck, const mesh::DistributedMesh& part) {
  io::RestartContent c;
  c.deck = restartDeckText(deck);
  c.nodes = part.numGlobalNodes;
  c.elements = part.numGlobalElements;
  // The same on any rank count and partition: a sum (mod 2^64) over nodes and elements, each hashed
  // with its global id, of every node once (by its owner) and every element once (by its part).
  const mesh::Mesh& local = part.local();
  const int dim = local.dimension;
  std::uint64_t sums[2] = {0, 0}, total[2] = {0, 0};
  for (std::size_t n = 0; n < part.nodeOwner.size(); ++n) {
    if (part.nodeOwner[n] != part.rank) continue;
    const std::uint64_t id = io::fnv1a(&part.part.globalNodes[n], sizeof(mesh::GlobalIndex));
    sums[0] += io::fnv1a(&local.coordinates[n * dim], dim * sizeof(double), id);
  }
  for (const auto& block : local.blocks) {
    const int npe = mesh::nodesPerCell(block.cellType);
    std::vector<mesh::GlobalIndex> nodes(static_cast<std::size_t>(npe));
    for (std::size_t k = 0; k < block.elements.size(); ++k) {
      for (int a = 0; a < npe; ++a) nodes[a] = part.part.globalNodes[block.connectivity[k * npe + a]];
      const std::uint64_t id = io::fnv1a(&part.part.globalElements[block.elements[k]], sizeof(mesh::GlobalIndex));
      sums[1] += io::fnv1a(nodes.data(), nodes.size() * sizeof(mesh::GlobalIndex), id);
    }
  }
  MPI_Allreduce(sums, total, 2, MPI_UINT64_T, MPI_SUM, part.comm);
  c.meshHash = io::fnv1a(total, sizeof total);
  return c;
}

RestartInput readRestart(const Teuchos::Comm<int>& comm, const std::string& path, const io::RestartContent& identity,
                         int dimension) {
  // Rank 0 reads the file; every rank decodes the same bytes, so every rank throws the same error.
  std::string bytes, error;
  if (comm.getRank() == 0) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      error = "--restart " + path + ": cannot open the restart file (no such file or no permission)";
    } else {
      std::ostringstream text;
      text << in.rdbuf();
      bytes = text.str();
    }
  }
  long long sizes[2] = {static_cast<long long>(bytes.size()), static_cast<long long>(error.size())};
  Teuchos::broadcast(comm, 0, 2, sizes);
  bytes.resize(static_cast<std::size_t>(sizes[0]));
  error.resize(static_cast<std::size_t>(sizes[1]));
  if (sizes[0] > 0) Teuchos::broadcast(comm, 0, static_cast<int>(sizes[0]), bytes.data());
  if (sizes[1] > 0) Teuchos::broadcast(comm, 0, static_cast<int>(sizes[1]), error.data());
  requireInput(error.empty(), error);

  RestartInput in;
  in.content = io::decodeRestart(bytes, path);
  const auto& c = in.content;
  const std::string difference = io::deckDifference(c.deck, identity.deck);
  requireInput(difference.empty(), "--restart " + path + ": written for another deck: " + difference);
  requireInput(c.nodes == identity.nodes && c.elements == identity.elements,
               "--restart " + path + ": written for another mesh (" + std::to_string(c.nodes) + " nodes and " +
                   std::to_string(c.elements) + " elements there, " + std::to_string(identity.nodes) + " and " +
                   std::to_string(identity.elements) + " here)");
  requireInput(c.meshHash == identity.meshHash, "--restart " + path +
                                                    ": written for another mesh (the same node and element counts, "
                                                    "other coordinates or connectivity)");
  // The history rows of steps 0..k (any value: a column may hold NaN where it has none).
  const StateField& rows =
      c.state.child("history").field("rows", StateField::Type::Double, {StateRecord::kAnyExtent, StateRecord::kAnyExtent});
  requireInput(rows.shape[0] > 0, "--restart " + path + ": corrupt restart file (no history rows)");
  for (std::size_t k = 0; k < rows.shape[0]; ++k)
    in.historyRows.emplace_back(rows.doubles.begin() + static_cast<std::ptrdiff_t>(k * rows.shape[1]),
                                rows.doubles.begin() + static_cast<std::ptrdiff_t>((k + 1) * rows.shape[1]));
  // Every rank reads its own nodes' displacements later: a file without all of them, or with a value that
  // is not finite, is refused here, on every rank alike.
  const StateRecord& nodes = c.state.child("nodes");
  StateTableReader table(nodes);
  std::vector<double> values;
  for (std::int64_t node = 0; node < c.nodes; ++node) {
    table.seek(node, "node " + std::to_string(node + 1));
    for (const char* column : {"displacement", "previous_displacement"}) {
      table(column, values);
      requireInput(values.size() == static_cast<std::size_t>(dimension),
                   "--restart " + path + ": nodes/" + column + ": " + std::to_string(values.size()) +
                       " components per node, the mesh has " + std::to_string(dimension));
    }
  }
  requireInput(table.rows() == static_cast<std::size_t>(c.nodes),
               "--restart " + path + ": nodes: " + std::to_string(table.rows()) + " rows, the mesh has " +
                   std::to_string(c.nodes) + " nodes");
  return in;
}

RunCheckpoints::RunCheckpoints(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const model::ContactMechanicsModel& model,
                               const output::ResultsOutput& results, std::string path, io::RestartContent identity,
                               int every, double maxWallSeconds, Clock::time_point runStart, bool verbose)
    : comm_(comm),
      model_(model),
      results_(results),
      path_(std::move(path)),
      identity_(std::move(identity)),
      every_(every),
      maxWallSeconds_(maxWallSeconds),
      runStart_(runStart),
      lastIncrement_(Clock::now()),
      verbose_(verbose) {
  if (const auto& end = batchJobEnd()) {  // rank 0 only
    jobEnd_ = end->time;
    jobName_ = end->job;
    jobEndMargin_ = end->marginSeconds;
    if (verbose_)
      std::printf("contessa: %s ends at %s (in %s s): the run stops with a restart file when the next increment "
                  "would not end %s s before\n",
                  jobName_.c_str(), clockTime(end->time).c_str(),
                  shortSeconds(std::chrono::duration<double>(end->time - std::chrono::system_clock::now()).count()).c_str(),
                  shortSeconds(jobEndMargin_).c_str());
  }
}

solvers::CheckpointControl::Decision RunCheckpoints::decide(int increments, bool converged) {
  const auto now = Clock::now();
  if (converged) {
    longestIncrement_ = std::max(longestIncrement_, std::chrono::duration<double>(now - lastIncrement_).count());
    lastIncrement_ = now;
  }
  // Rank 0's clock decides the wall time; any rank's signal counts (mpirun may deliver it to some only).
  int local[2] = {pendingStopSignal(), 0}, agreed[2] = {0, 0};
  const double elapsed = std::chrono::duration<double>(now - runStart_).count();
  const double needed = 1.5 * longestIncrement_ + writeSeconds_;
  if (comm_->getRank() == 0 && maxWallSeconds_ > 0 && elapsed + needed > maxWallSeconds_) local[1] = 1;
  // The batch job's limit: Slurm ends the job then, whatever is under way, so the next increment, the
  // restart file and the margin (the process's exit, the job script's last steps) must all fit before it.
  double jobLeft = 0;
  if (jobEnd_) {
    jobLeft = std::chrono::duration<double>(*jobEnd_ - std::chrono::system_clock::now()).count();
    if (needed + jobEndMargin_ > jobLeft) local[1] = std::max(local[1], 2);
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 2, local, agreed);
  Decision d;
  if (agreed[0] != 0) {
    d.stop = true;
    d.reason = signalName(agreed[0]) + " received";
  } else if (agreed[1] == 2) {
    d.stop = true;
    d.reason = "the time limit of " + (jobName_.empty() ? std::string("the batch job") : jobName_) + " would not hold another increment (" + shortSeconds(jobLeft) +
               " s left, the longest increment " + shortSeconds(longestIncrement_) + " s)";
  } else if (agreed[1] != 0) {
    d.stop = true;
    d.reason = "Problem/Output/Checkpoint/Max Wall Time = " + shortSeconds(maxWallSeconds_) + " s would not hold another " +
               "increment (" + shortSeconds(elapsed) + " s elapsed, the longest increment " +
               shortSeconds(longestIncrement_) + " s)";
  }
  d.write = d.stop || (converged && every_ > 0 && increments % every_ == 0);
  stopping_ = d.stop;
  return d;
}

void RunCheckpoints::write(StateRecord driverState) {
  const auto start = Clock::now();
  // Every rank's part of the state (its elements, slave nodes, displacements), gathered to rank 0 as
  // encoded pieces; rank 0 merges them (rows sorted by id), adds the history rows and writes the file.
  io::RestartContent piece;
  model_.saveCommittedState(piece.state);
  piece.state.merge(driverState);
  const std::string bytes = io::encodeRestart(std::move(piece));
  const int ranks = comm_->getSize();
  // MPI_Gatherv counts and offsets are int: refused alike on every rank beyond 2 GiB in all.
  const long long mine = static_cast<long long>(bytes.size());
  long long total = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 1, &mine, &total);
  if (total > static_cast<long long>(std::numeric_limits<int>::max())) {
    failure_ = "cannot write the restart file " + path_ + ": its " + std::to_string(total) +
               " bytes exceed the 2 GiB one gather to rank 0 can carry (not supported yet)";
    throw std::runtime_error(failure_);
  }
  const int mySize = static_cast<int>(bytes.size());
  std::vector<int> sizes(static_cast<std::size_t>(ranks), 0), offsets(static_cast<std::size_t>(ranks), 0);
  const MPI_Comm mpi = *Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm_, true)->getRawMpiComm();
  MPI_Gather(&mySize, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, mpi);
  std::string all;
  if (comm_->getRank() == 0) {
    for (int r = 1; r < ranks; ++r) offsets[r] = offsets[r - 1] + sizes[r - 1];
    all.resize(static_cast<std::size_t>(offsets[ranks - 1] + sizes[ranks - 1]));
  }
  MPI_Gatherv(bytes.data(), mySize, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR, 0, mpi);
  std::string error;
  if (comm_->getRank() == 0) {
    io::RestartContent content = identity_;
    for (int r = 0; r < ranks; ++r)
      content.state.merge(io::decodeRestart(all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(sizes[r])),
                                            path_).state);
    const auto& rows = results_.historyRows();
    std::vector<double> table;
    for (const auto& row : rows) table.insert(table.end(), row.begin(), row.end());
    content.state.child("history").put("rows", std::move(table), {rows.size(), rows.empty() ? 0 : rows[0].size()});
    error = io::writeRestartFile(path_, std::move(content));
  }
  int size = static_cast<int>(error.size());
  Teuchos::broadcast(*comm_, 0, &size);
  error.resize(static_cast<std::size_t>(size));
  if (size > 0) Teuchos::broadcast(*comm_, 0, size, error.data());
  if (!error.empty()) {
    failure_ = "cannot write the restart file " + error;
    throw std::runtime_error(failure_);
  }
  writeSeconds_ = std::chrono::duration<double>(Clock::now() - start).count();
  if (comm_->getRank() == 0 && verbose_ && !stopping_) {  // a stop says so in its own line
    std::printf("contessa: checkpoint: wrote %s at step %lld\n", path_.c_str(),
                static_cast<long long>(results_.historyRows().size()) - 1);
    std::fflush(stdout);
  }
}

}  // namespace contessa::app
