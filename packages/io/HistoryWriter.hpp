#pragma once
// Per-step history as CSV (one row per accepted step), readable by spreadsheets and pandas.
#include <fstream>
#include <string>
#include <vector>

namespace contessa::io {

/// Writes the header on construction (truncating `path`), then one row per writeRow call. Every row
/// is flushed, so a run that dies keeps the rows written so far. Columns named in `integerColumns`
/// (step, attempts, iteration and contact counts) print as integers (rounded), the others with 12
/// significant digits. Throws std::runtime_error naming the file if it cannot be written, and
/// std::invalid_argument for a row of the wrong length or an unknown integer column.
class HistoryWriter {
 public:
  HistoryWriter(const std::string& path, std::vector<std::string> columns,
                const std::vector<std::string>& integerColumns = {});

  void writeRow(const std::vector<double>& values);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  int rowsWritten() const { return rows_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::vector<bool> integer_;
  std::ofstream out_;
  int rows_ = 0;
};

}  // namespace contessa::io
