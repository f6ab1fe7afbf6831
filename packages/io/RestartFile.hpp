#pragma once
// The restart file `<name>.restart` (docs/user-guide.md, "Checkpoint and restart"): the committed state of
// a run at a converged increment, written by rank 0 and read back by every rank. Independent of the
// rank count: every record is keyed by a global id (element, node, slave node) and the records are sorted
// by key. Pure C++: what goes into the records is the business of the model, the driver and the output.
//
// Layout (native little-endian doubles and integers; the machine that reads is the kind that wrote):
//   "CONTESSA RESTART" (16 bytes), uint32 format version, uint64 payload bytes, uint64 FNV-1a of the payload
//   payload: deck text (uint64 length + bytes), int64 nodes, int64 elements, uint64 mesh hash,
//            uint64 record count, records (int64 kind, int64 id, uint64 n, n doubles)
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace contessa::io {

/// One keyed block of numbers (integers are stored as doubles: exact below 2^53).
struct RestartRecord {
  std::int64_t kind = 0, id = 0;
  std::vector<double> values;
};

struct RestartContent {
  /// The run's deck in "path = value" lines, run-control parameters left out (restartDeckText): what a
  /// restart must match.
  std::string deck;
  std::int64_t nodes = 0, elements = 0;
  std::uint64_t meshHash = 0;
  std::vector<RestartRecord> records;  ///< any order; written sorted by (kind, id)
};

// 2: the mesh fingerprint sums per-node and per-element hashes by global id (any partition alike).
constexpr std::uint32_t kRestartFormatVersion = 2;

/// What a record holds (RestartRecord::kind), and what its id counts.
namespace restart_kind {
constexpr std::int64_t kRun = 1;             ///< id 0: the continuation's scalars (solvers::ContinuationDriver)
constexpr std::int64_t kStepSize = 2;        ///< id 0: the step-size strategy's state
constexpr std::int64_t kHistoryRow = 3;      ///< id: history row (= step)
constexpr std::int64_t kDisplacement = 10;   ///< id: node; the committed displacements x_k
constexpr std::int64_t kPreviousDisplacement = 11;  ///< id: node; x_{k-1} (the secant predictor's)
constexpr std::int64_t kElementState = 20;   ///< id: element; its committed internal variables
constexpr std::int64_t kContactSlave = 100;  ///< + interface index; id: slave node index
constexpr std::int64_t kContactMaster = 200; ///< + interface index; id 0: master facets' committed positions
}  // namespace restart_kind

/// 64-bit FNV-1a, continued from `hash`.
std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash = 14695981039346656037ULL);

/// The file's bytes.
std::string encodeRestart(RestartContent content);
/// Parses the bytes of `path`; throws InputError "--restart PATH: ..." naming what is wrong (not a restart
/// file, another format version, truncated, corrupt).
RestartContent decodeRestart(const std::string& bytes, const std::string& path);
/// Reads and decodes `path` (InputError when missing or unreadable).
RestartContent readRestartFile(const std::string& path);
/// Writes `bytes` to `path` atomically: a temporary file beside it, fsync, rename. "" or the reason.
std::string writeFileAtomically(const std::string& path, const std::string& bytes);

/// "" when `saved` (the restart file's deck text) matches `current`; otherwise what differs, in words:
/// "Piro/LOCA/Step Size/Contacts Per Step is 2 in the restart file, 3 here".
std::string deckDifference(const std::string& saved, const std::string& current);

/// The records by key, for look-ups.
class RestartRecords {
 public:
  explicit RestartRecords(const std::vector<RestartRecord>& records);
  /// The record (kind, id), or nullptr.
  const std::vector<double>* find(std::int64_t kind, std::int64_t id) const;
  /// The record (kind, id); throws InputError naming `what` when it is missing.
  const std::vector<double>& at(std::int64_t kind, std::int64_t id, const std::string& what) const;

 private:
  std::map<std::pair<std::int64_t, std::int64_t>, const std::vector<double>*> index_;
};

}  // namespace contessa::io
