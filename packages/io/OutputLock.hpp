#pragma once
// One run at a time per output: two runs writing `<name>.exo` and `<name>.history.csv` into the same
// directory would silently interleave their steps. A run holds an flock(2) on `<directory>/<name>.lock`
// while it writes; the file records the holder (PID, host, start time) for the message another run
// shows. The kernel drops the lock when the holding process ends, however it ends (kill -9, a
// crash), so a stale lock file never blocks the next run.
#include <string>

namespace contessa::io {

class OutputLock {
 public:
  /// Takes the lock, or throws InputError naming the directory and the run that holds it (or why
  /// the lock file cannot be created). Where the file system has no flock (some network file
  /// systems), `warning()` says so and the run goes on unprotected.
  OutputLock(const std::string& directory, const std::string& name);
  /// Removes the lock file and releases the lock.
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  const std::string& path() const { return path_; }
  const std::string& warning() const { return warning_; }

 private:
  std::string path_, warning_;
  int fd_ = -1;
};

}  // namespace contessa::io
