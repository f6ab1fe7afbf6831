#pragma once
// Disk space for files that must never be left half written. A step is appended only after the
// blocks it will need have been reserved past the end of the file, so that a full disk (or quota)
// is found before the step is written, with the file still valid, and not in the middle of it.
#include <string>

namespace contessa::io {

/// Reserves `bytes` of disk blocks after the current end of the open file `fd` without changing the
/// file's size (fallocate with FALLOC_FL_KEEP_SIZE): later writes there need no new block. Where the
/// file system cannot reserve blocks, checks instead that statvfs reports that much free space.
/// Returns 0, or the errno that says why not (ENOSPC, EDQUOT, ...).
int reserveAfterEnd(int fd, long long bytes);

/// Releases blocks reserved past the end of the file (best effort, at close).
void releaseAfterEnd(int fd);

/// strerror(error) as a std::string.
std::string systemMessage(int error);

}  // namespace contessa::io
