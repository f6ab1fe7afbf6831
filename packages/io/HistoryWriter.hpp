#pragma once
// Per-step history as CSV (one row per accepted step), readable by spreadsheets and pandas.
#include <string>
#include <vector>

namespace contessa::io {

/// Writes the header on construction (truncating `path`), then one row per writeRow call. Each row
/// goes to the file in one write(2) after the disk space for it has been reserved, so a run that
/// dies, or a full disk, leaves whole rows only. Columns named in `integerColumns` (step, attempts,
/// iteration and contact counts) print as integers (rounded), the others with 12 significant digits.
/// Throws OutputWriteError naming the file and the system's reason if it cannot be written, and
/// std::invalid_argument for a row of the wrong length or an unknown integer column.
class HistoryWriter {
 public:
  HistoryWriter(const std::string& path, std::vector<std::string> columns,
                const std::vector<std::string>& integerColumns = {});
  ~HistoryWriter();
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  void writeRow(const std::vector<double>& values);
  /// Reserves the disk space for the next row (writeRow does too). Called before the other files of
  /// the same step are written, a full disk then stops the run before any of them is.
  void reserveRow();

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  int rowsWritten() const { return rows_; }

 private:
  /// Appends `text` whole or not at all (a short write is cut off again).
  void append(const std::string& text, const std::string& what);

  std::string path_;
  std::vector<std::string> columns_;
  std::vector<bool> integer_;
  int fd_ = -1;
  int rows_ = 0;
};

}  // namespace contessa::io
