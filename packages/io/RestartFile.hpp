#pragma once
// The restart file `<name>.restart` (docs/user-guide.md, "Checkpoint and restart"): the committed state of
// a run at a converged increment, written by rank 0 and read back by every rank. Independent of the
// rank count: the rows of every table (nodes, elements, slave nodes) are keyed by a global id and sorted
// by it. What goes into the state is the business of the model, the driver and the output.
//
// The file is netCDF-4 (HDF5), so `ncdump` shows it: global attributes title ("Contessa restart file"),
// format_version, deck, nodes, elements, mesh_hash and checksum; the state as groups and variables, one
// group per StateRecord and one variable per field (common/StateRecord.hpp). docs/user-guide.md,
// "Checkpoint and restart", lists the groups.
#include <cstdint>
#include <string>

#include "common/StateRecord.hpp"

namespace contessa::io {

struct RestartContent {
  /// The run's deck in "path = value" lines, run-control parameters left out (restartDeckText): what a
  /// restart must match.
  std::string deck;
  std::int64_t nodes = 0, elements = 0;
  std::uint64_t meshHash = 0;
  /// The state by name: the continuation, step size, nodes, elements, contact interfaces, history.
  StateRecord state;
};

// 2: the mesh fingerprint sums per-node and per-element hashes by global id (any partition alike).
// 3: netCDF-4 with named fields (before: a binary file of positional records, "CONTESSA RESTART" header).
constexpr std::uint32_t kRestartFormatVersion = 3;

using contessa::fnv1a;

/// The file's bytes (an in-memory netCDF-4 image: what the ranks send to rank 0).
std::string encodeRestart(RestartContent content);
/// Parses the bytes of `path`; throws InputError "--restart PATH: ..." naming what is wrong (not a restart
/// file, another format version, truncated, damaged, corrupt). The state's origin is "--restart PATH", so
/// its fields' errors name the file.
RestartContent decodeRestart(const std::string& bytes, const std::string& path);
/// Reads and decodes `path` (InputError when missing or unreadable).
RestartContent readRestartFile(const std::string& path);
/// Writes the restart file `path` atomically: a temporary file beside it, fsync, rename. "" or the reason.
std::string writeRestartFile(const std::string& path, RestartContent content);
/// Writes `bytes` to `path` atomically: a temporary file beside it, fsync, rename. "" or the reason.
std::string writeFileAtomically(const std::string& path, const std::string& bytes);

/// "" when `saved` (the restart file's deck text) matches `current`; otherwise what differs, in words:
/// "Piro/LOCA/Step Size/Contacts Per Step is 2 in the restart file, 3 here".
std::string deckDifference(const std::string& saved, const std::string& current);

}  // namespace contessa::io
