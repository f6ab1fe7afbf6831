#include "RunReport.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>

namespace contessa::app {
namespace {

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else out += c;
  }
  return out + "\"";
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

double mebibytes(long long bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

}  // namespace

long long peakResidentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atoll(line.c_str() + 6) * 1024LL;  // "VmHWM:   123456 kB"
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0) return static_cast<long long>(usage.ru_maxrss) * 1024LL;  // KiB on Linux
  return 0;
}

void gatherPeakMemory(const Teuchos::Comm<int>& comm, RunReport& report) {
  const long long mine = peakResidentBytes();
  std::vector<long long> all(static_cast<std::size_t>(comm.getSize()), 0);
  Teuchos::gatherAll(comm, 1, &mine, comm.getSize(), all.data());
  report.peakBytesPerRank = all;
}

void gatherMeshParts(const Teuchos::Comm<int>& comm, const mesh::DistributedMesh& part, RunReport& report) {
  const long long mine[3] = {static_cast<long long>(part.part.globalElements.size()),
                             static_cast<long long>(part.part.globalNodes.size()), static_cast<long long>(part.bytes())};
  std::vector<long long> all(3 * static_cast<std::size_t>(comm.getSize()), 0);
  Teuchos::gatherAll(comm, 3, mine, static_cast<int>(all.size()), all.data());
  report.partElements.clear();
  report.partNodes.clear();
  report.partBytes.clear();
  for (std::size_t r = 0; r < all.size(); r += 3) {
    report.partElements.push_back(all[r]);
    report.partNodes.push_back(all[r + 1]);
    report.partBytes.push_back(all[r + 2]);
  }
  report.meshElements = part.numGlobalElements;
  report.meshNodes = part.numGlobalNodes;
}

EarlierJobs earlierJobs(const std::vector<std::string>& columns, const std::vector<std::vector<double>>& rows) {
  EarlierJobs e;
  if (rows.empty()) return e;
  e.step = static_cast<int>(rows.size()) - 1;
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  const std::size_t wall = column("wall_s");
  if (wall < rows.back().size() && std::isfinite(rows.back()[wall])) e.wallSeconds = rows.back()[wall];
  return e;
}

std::string summaryLine(const RunReport& r) {
  const auto& s = r.summary;
  const auto [lo, hi] = std::minmax_element(r.peakBytesPerRank.begin(), r.peakBytesPerRank.end());
  std::ostringstream out;
  out << "contessa: summary: ";
  if (r.earlier) {
    // The driver's increment count is the run's; Newton iterations and wall time are this job's.
    const EarlierJobs& e = *r.earlier;
    out << "this job " << s.increments - e.step << " increments (steps " << e.step + 1 << " to " << s.increments
        << "), " << s.newtonIterations << " Newton iterations, wall " << number(r.wallSeconds) << " s; whole run "
        << s.increments << " increments, " << s.failedAttempts << " failed attempts, "
        << s.runNewtonIterations << " Newton iterations, wall "
        << number(e.wallSeconds + r.wallSeconds) << " s; this job " << s.linearIterations << " linear iterations";
  } else {
    out << s.increments << " increments, " << s.failedAttempts << " failed attempts, " << s.newtonIterations
        << " Newton iterations, " << s.linearIterations << " linear iterations, wall " << number(r.wallSeconds) << " s";
  }
  out << ", peak memory per rank " << number(mebibytes(r.peakBytesPerRank.empty() ? 0 : *lo))
      << " to " << number(mebibytes(r.peakBytesPerRank.empty() ? 0 : *hi)) << " MiB (" << r.ranks << " rank(s))";
  return out.str();
}

std::string summaryJson(const RunReport& r) {
  const auto& s = r.summary;
  std::ostringstream out;
  long long lo = 0, hi = 0;
  if (!r.peakBytesPerRank.empty()) {
    lo = *std::min_element(r.peakBytesPerRank.begin(), r.peakBytesPerRank.end());
    hi = *std::max_element(r.peakBytesPerRank.begin(), r.peakBytesPerRank.end());
  }
  out << "{\n"
      << "  \"deck\": " << jsonString(r.deck) << ",\n"
      << "  \"ranks\": " << r.ranks << ",\n"
      << "  \"finished\": " << (s.finished ? "true" : "false") << ",\n"
      << "  \"exit_status\": " << r.exitStatus << ",\n"
      << "  \"stop_reason\": " << jsonString(s.finished ? "" : s.message) << ",\n"
      << "  \"final_load_factor\": " << number(s.finalLambda) << ",\n"
      << "  \"increments\": " << s.increments << ",\n"
      << "  \"failed_attempts\": " << s.failedAttempts << ",\n"
      << "  \"newton_iterations\": " << s.newtonIterations << ",\n"
      << "  \"linear_solves\": " << s.linearSolves << ",\n"
      << "  \"linear_iterations\": " << s.linearIterations << ",\n"
      << "  \"linear_solver\": " << jsonString(r.linearSolver) << ",\n"
      << "  \"linear_solver_automatic\": " << (r.linearSolverAutomatic ? "true" : "false") << ",\n"
      << "  \"preconditioner_new_graph_setups\": " << r.preconditionerRebuildsOnNewGraph << ",\n"
      << "  \"preconditioner_refused_reuses\": " << r.preconditionerRefusedReuses << ",\n"
      << "  \"preconditioner_reused_setups\": " << r.preconditionerReusedSetUps << ",\n"
      << "  \"preconditioner_pattern_restarts\": " << r.preconditionerPatternRestarts << ",\n"
      << "  \"preconditioner_coarse_zero_restarts\": " << r.preconditionerCoarseZeroRestarts << ",\n"
      << "  \"direct_factorizations\": " << r.directFactorizations << ",\n"
      << "  \"symmetric_factorizations\": " << r.symmetricFactorizations << ",\n"
      << "  \"reused_factorizations\": " << r.reusedFactorizations << ",\n"
      << "  \"preconditioner_unchanged_setups\": " << r.preconditionerUnchangedSetUps << ",\n"
      << "  \"preconditioner_large_change_restarts\": " << r.preconditionerLargeChangeRestarts << ",\n"
      << "  \"graph_rebuilds\": " << r.graphRebuilds << ",\n"
      << "  \"graph_rebuild_seconds\": " << number(r.graphRebuildSeconds) << ",\n"
      << "  \"wall_seconds\": " << number(r.wallSeconds) << ",\n"
      << "  \"peak_memory_bytes\": {\"min\": " << lo << ", \"max\": " << hi << ", \"per_rank\": [";
  for (std::size_t k = 0; k < r.peakBytesPerRank.size(); ++k) out << (k ? ", " : "") << r.peakBytesPerRank[k];
  out << "]},\n";
  const auto list = [&out](const std::vector<long long>& values) {
    out << "[";
    for (std::size_t k = 0; k < values.size(); ++k) out << (k ? ", " : "") << values[k];
    out << "]";
  };
  out << "  \"mesh\": {\"elements\": " << r.meshElements << ", \"nodes\": " << r.meshNodes << ", \"part_elements\": ";
  list(r.partElements);
  out << ", \"part_nodes\": ";
  list(r.partNodes);
  out << ", \"part_bytes\": ";
  list(r.partBytes);
  out << "}";
  // Both scopes of a continued run: this job (after the restart file's step) and the whole run.
  const EarlierJobs e = r.earlier.value_or(EarlierJobs{});
  out << ",\n  \"this_job\": {\"first_step\": " << e.step + 1 << ", \"increments\": " << s.increments - e.step
      << ", \"newton_iterations\": " << s.newtonIterations << ", \"wall_seconds\": " << number(r.wallSeconds) << "}";
  out << ",\n  \"whole_run\": {\"continued\": " << (r.earlier ? "true" : "false") << ", \"increments\": " << s.increments
      << ", \"newton_iterations\": " << s.runNewtonIterations
      << ", \"wall_seconds\": " << number(e.wallSeconds + r.wallSeconds) << "}\n}\n";
  return out.str();
}

}  // namespace contessa::app
