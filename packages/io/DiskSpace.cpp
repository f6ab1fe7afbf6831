#include "io/DiskSpace.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace contessa::io {

int reserveAfterEnd(int fd, long long bytes) {
  struct stat info {};
  if (fstat(fd, &info) != 0) return errno;
  if (fallocate(fd, FALLOC_FL_KEEP_SIZE, info.st_size, bytes) == 0) return 0;
  const int error = errno;
  if (error != EOPNOTSUPP && error != ENOSYS) return error;
  // No block reservation on this file system (some network file systems): the free space is the
  // best evidence there is.
  struct statvfs fs {};
  if (fstatvfs(fd, &fs) != 0) return 0;  // nothing known: let the write itself find out
  const long double available = static_cast<long double>(fs.f_bavail) * fs.f_frsize;
  return available < bytes ? ENOSPC : 0;
}

void releaseAfterEnd(int fd) {
  struct stat info {};
  if (fstat(fd, &info) != 0) return;
  // Blocks past the end are those of FALLOC_FL_KEEP_SIZE. File systems differ in which call frees
  // them: a hole punched there (tmpfs) or a truncation to the same size (ext4).
  if (fallocate(fd, FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE, info.st_size, 1LL << 30) != 0) {
    // best effort: the blocks only cost space until the file is deleted
  }
  if (ftruncate(fd, info.st_size) != 0) {
    // as above
  }
}

std::string systemMessage(int error) { return std::strerror(error); }

}  // namespace contessa::io
