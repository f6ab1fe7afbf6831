#pragma once
// Internal to the mesh and io packages (includes exodusII.h): include from .cpp files only.
#include <exodusII.h>

#include <string>
#include <utility>

namespace contessa::mesh::detail {

/// Owns an Exodus file id so that every exit path, including exceptions, closes the file.
class ExodusFile {
 public:
  ExodusFile(std::string path, int id) : path_(std::move(path)), id_(id) {}
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;
  ~ExodusFile() {
    if (id_ >= 0) ex_close(id_);  // already failing: a second error would only hide the first
  }

  int id() const { return id_; }
  const std::string& path() const { return path_; }

  /// Closing flushes buffered data, so its status matters when writing; returns ex_close's code.
  int close() {
    const int status = ex_close(id_);
    id_ = -1;
    return status;
  }

  /// The library's last error message, for diagnostics ("" if none).
  static std::string lastError() {
    const char* message = nullptr;
    const char* function = nullptr;
    int code = 0;
    ex_get_err(&message, &function, &code);
    std::string text;
    if (function && *function) text += std::string(function) + ": ";
    if (message) text += message;
    return text;
  }

 private:
  std::string path_;
  int id_;
};

}  // namespace contessa::mesh::detail
