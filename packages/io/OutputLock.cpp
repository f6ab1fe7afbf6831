#include "io/OutputLock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>

#include "common/Error.hpp"
#include "io/DiskSpace.hpp"

namespace contessa::io {

namespace {

std::string hostName() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) return "unknown host";
  return host;
}

std::string now() {
  const std::time_t t = std::time(nullptr);
  char text[32] = {};
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", std::localtime(&t));
  return text;
}

// What the holder wrote into the lock file ("PID 1234 on host node7 since 2024-05-01 10:00:00").
std::string holder(int fd) {
  char text[512] = {};
  const ssize_t n = pread(fd, text, sizeof text - 1, 0);
  std::string who(text, n > 0 ? static_cast<size_t>(n) : 0);
  while (!who.empty() && (who.back() == '\n' || who.back() == ' ')) who.pop_back();
  return who.empty() ? "a run that is starting" : who;
}

bool sameFile(int fd, const std::string& path) {
  struct stat open {}, named {};
  return fstat(fd, &open) == 0 && stat(path.c_str(), &named) == 0 && open.st_dev == named.st_dev &&
         open.st_ino == named.st_ino;
}

}  // namespace

OutputLock::OutputLock(const std::string& directory, const std::string& name)
    : path_(directory + "/" + name + ".lock") {
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw InputError("--output-dir " + directory + ": cannot write into the directory: " + systemMessage(errno) +
                       " (creating " + path_ + ")");
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      if (error == EWOULDBLOCK) {
        const std::string who = holder(fd_);
        ::close(fd_);
        fd_ = -1;
        throw InputError("--output-dir " + directory + ": another run is writing " + name + ".exo there (" + who +
                         "; lock file " + path_ + ")");
      }
      // No flock on this file system: run, but say that concurrent runs are not detected.
      warning_ = "cannot lock " + path_ + " (" + systemMessage(error) +
                 "): another run writing into the same directory would not be detected";
      break;
    }
    // The previous holder removes the file when it ends: a lock taken on a file that is no longer
    // the one at `path_` protects nothing, so start again with the current file.
    if (sameFile(fd_, path_)) break;
    ::close(fd_);
  }
  const std::string who = "PID " + std::to_string(getpid()) + " on host " + hostName() + " since " + now() + "\n";
  if (ftruncate(fd_, 0) != 0 || pwrite(fd_, who.data(), who.size(), 0) != static_cast<ssize_t>(who.size())) {
    // The lock holds without the record; another run then names the holder "a run that is starting".
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  // Unlink before unlocking, so that no other run can take the lock on a file about to disappear
  // (a run that opened it before the unlink notices with sameFile and starts again).
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace contessa::io
