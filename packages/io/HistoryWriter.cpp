#include "io/HistoryWriter.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "io/DiskSpace.hpp"
#include "io/OutputWriteError.hpp"

namespace contessa::io {

namespace {

// RFC 4180 quoting, only where a name would otherwise break the row apart.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// Room for a few rows at a time: reserving is a system call, a row is ~200 bytes.
constexpr long long kReserveBytes = 16 * 1024;

}  // namespace

HistoryWriter::HistoryWriter(const std::string& path, std::vector<std::string> columns,
                             const std::vector<std::string>& integerColumns)
    : path_(path), columns_(std::move(columns)), integer_(columns_.size(), false) {
  for (const auto& name : integerColumns) {
    auto it = std::find(columns_.begin(), columns_.end(), name);
    if (it == columns_.end())
      throw std::invalid_argument(path_ + ": integer column '" + name + "' is not one of the columns");
    integer_[static_cast<size_t>(it - columns_.begin())] = true;
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw OutputWriteError(path_, "cannot create", systemMessage(errno));
  std::string header;
  for (size_t c = 0; c < columns_.size(); ++c) header += (c ? "," : "") + csvField(columns_[c]);
  try {
    append(header + "\n", "cannot write the header to");
  } catch (...) {  // the destructor does not run for a constructor that throws
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

HistoryWriter::~HistoryWriter() {
  if (fd_ < 0) return;
  releaseAfterEnd(fd_);
  ::close(fd_);
}

void HistoryWriter::writeRow(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument(path_ + ": history row has " + std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  std::ostringstream row;
  row << std::setprecision(12);
  for (size_t c = 0; c < values.size(); ++c) {
    if (c) row << ',';
    if (integer_[c] && std::isfinite(values[c]))
      row << std::llround(values[c]);
    else
      row << values[c];
  }
  row << '\n';
  append(row.str(), "cannot write row " + std::to_string(rows_ + 1) + " to");
  ++rows_;
}

void HistoryWriter::reserveRow() {
  if (const int error = reserveAfterEnd(fd_, kReserveBytes))
    throw OutputWriteError(path_, "cannot write row " + std::to_string(rows_ + 1) + " to", systemMessage(error));
}

void HistoryWriter::append(const std::string& text, const std::string& what) {
  struct stat info {};
  if (fstat(fd_, &info) != 0) throw OutputWriteError(path_, what, systemMessage(errno));
  if (const int error = reserveAfterEnd(fd_, std::max<long long>(kReserveBytes, 2 * text.size())))
    throw OutputWriteError(path_, what, systemMessage(error));
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      if (ftruncate(fd_, info.st_size) != 0) {
        // the partial row stays; the error below still ends the run
      }
      throw OutputWriteError(path_, what, systemMessage(error));
    }
    done += static_cast<size_t>(n);
  }
}

}  // namespace contessa::io
