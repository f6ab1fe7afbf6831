#include "io/HistoryWriter.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <stdexcept>

namespace contessa::io {

namespace {

// RFC 4180 quoting, only where a name would otherwise break the row apart.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

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
  out_.open(path_, std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error(path_ + ": cannot create history file");
  for (size_t c = 0; c < columns_.size(); ++c) out_ << (c ? "," : "") << csvField(columns_[c]);
  out_ << '\n' << std::flush;
  if (!out_) throw std::runtime_error(path_ + ": cannot write history file header");
  out_ << std::setprecision(12);
}

void HistoryWriter::writeRow(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument(path_ + ": history row has " + std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  for (size_t c = 0; c < values.size(); ++c) {
    if (c) out_ << ',';
    if (integer_[c] && std::isfinite(values[c]))
      out_ << std::llround(values[c]);
    else
      out_ << values[c];
  }
  out_ << '\n' << std::flush;
  if (!out_) throw std::runtime_error(path_ + ": cannot write history row " + std::to_string(rows_ + 1));
  ++rows_;
}

}  // namespace contessa::io
