#pragma once
// An output file that could not be written (a full disk, a directory that is not writable, a path
// that is a directory). The message reads "<action> <path>: <reason>", e.g. "cannot write row 12 to
// out/tube.history.csv: No space left on device"; path and reason are kept for callers that say
// more about what was being written.
#include <stdexcept>
#include <string>

namespace contessa::io {

class OutputWriteError : public std::runtime_error {
 public:
  OutputWriteError(const std::string& path, const std::string& action, const std::string& reason)
      : std::runtime_error(action + " " + path + ": " + reason), path_(path), reason_(reason) {}

  const std::string& path() const { return path_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string path_, reason_;
};

}  // namespace contessa::io
