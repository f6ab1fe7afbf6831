#include "common/StateRecord.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <sstream>

#include "common/Error.hpp"

namespace contessa {

std::size_t StateField::count() const {
  return std::accumulate(shape.begin(), shape.end(), std::size_t{1}, std::multiplies<>());
}

std::string typeName(StateField::Type type) {
  switch (type) {
    case StateField::Type::Double: return "double";
    case StateField::Type::Int64: return "int64";
    case StateField::Type::Text: return "text";
  }
  return "?";
}

std::string shapeText(const std::vector<std::size_t>& shape) {
  std::string out = "[";
  for (std::size_t i = 0; i < shape.size(); ++i)
    out += (i > 0 ? ", " : "") + (shape[i] == StateRecord::kAnyExtent ? std::string("n") : std::to_string(shape[i]));
  return out + "]";
}

// ---- StateRecord

void StateRecord::put(const std::string& name, std::vector<double> values, std::vector<std::size_t> shape) {
  StateField f;
  f.type = StateField::Type::Double;
  f.shape = std::move(shape);
  f.doubles = std::move(values);
  putField(name, std::move(f));
}

void StateRecord::put(const std::string& name, std::vector<std::int64_t> values, std::vector<std::size_t> shape) {
  StateField f;
  f.type = StateField::Type::Int64;
  f.shape = std::move(shape);
  f.integers = std::move(values);
  putField(name, std::move(f));
}

void StateRecord::putText(const std::string& name, std::string text) {
  StateField f;
  f.type = StateField::Type::Text;
  f.text = std::move(text);
  putField(name, std::move(f));
}

void StateRecord::putField(const std::string& name, StateField field) {
  const std::size_t n = field.type == StateField::Type::Double  ? field.doubles.size()
                        : field.type == StateField::Type::Int64 ? field.integers.size()
                                                                : 1;
  if (n != field.count() || (field.type == StateField::Type::Text && !field.shape.empty()))
    throw std::logic_error("StateRecord: field " + path_ + name + " has " + std::to_string(n) + " values for shape " +
                           shapeText(field.shape));
  fields_[name] = std::move(field);
}

StateRecord& StateRecord::child(const std::string& name) {
  auto [it, created] = children_.try_emplace(name);
  if (created) {
    it->second.path_ = path_ + name + "/";
    it->second.origin_ = origin_;
  }
  return it->second;
}

void StateRecord::fail(const std::string& name, const std::string& what) const {
  throw InputError((origin_.empty() ? std::string("state") : origin_) + ": " + path_ + name + ": " + what);
}

const StateField& StateRecord::anyField(const std::string& name) const {
  const auto it = fields_.find(name);
  if (it == fields_.end()) fail(name, "missing (this Contessa needs it)");
  read_.insert(name);
  return it->second;
}

const StateField& StateRecord::field(const std::string& name, StateField::Type type,
                                     const std::vector<std::size_t>& shape) const {
  const StateField& f = anyField(name);
  bool fits = f.type == type && f.shape.size() == shape.size();
  for (std::size_t i = 0; fits && i < shape.size(); ++i) fits = shape[i] == kAnyExtent || shape[i] == f.shape[i];
  if (!fits)
    fail(name, typeName(f.type) + " " + shapeText(f.shape) + " in the file, " + typeName(type) + " " + shapeText(shape) +
                   " expected");
  return f;
}

void StateRecord::requireFinite(const std::string& name, const double* values, std::size_t n,
                                StateValues allowed) const {
  if (allowed == StateValues::AnyDouble) return;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i])) {
      std::ostringstream text;
      text << values[i];
      fail(name, (n > 1 ? "value " + std::to_string(i) + " is " : std::string("is ")) + text.str() +
                     ", a finite number expected");
    }
}

double StateRecord::getDouble(const std::string& name, StateValues values) const {
  const double v = field(name, StateField::Type::Double, {}).doubles[0];
  requireFinite(name, &v, 1, values);
  return v;
}

std::int64_t StateRecord::getInt(const std::string& name) const {
  return field(name, StateField::Type::Int64, {}).integers[0];
}

const std::string& StateRecord::getText(const std::string& name) const {
  return field(name, StateField::Type::Text, {}).text;
}

const StateRecord& StateRecord::child(const std::string& name) const {
  const auto it = children_.find(name);
  if (it == children_.end()) fail(name, "missing (this Contessa needs it)");
  return it->second;
}

const StateRecord& StateRecord::claim(const std::string& name) const {
  const StateRecord& c = child(name);
  c.claimed_ = true;
  return c;
}

std::string StateRecord::firstUnread() const {
  for (const auto& [name, f] : fields_)
    if (read_.count(name) == 0) return path_ + name;
  for (const auto& [name, c] : children_) {
    if (c.claimed_) continue;
    const std::string unread = c.firstUnread();
    if (!unread.empty()) return unread;
  }
  return "";
}

void StateRecord::requireAllRead() const {
  const std::string unread = firstUnread();
  if (!unread.empty())
    throw InputError((origin_.empty() ? std::string("state") : origin_) + ": " + unread +
                     ": unknown field (this Contessa does not read it: written by another version?)");
}

void StateRecord::setOrigin(const std::string& origin) {
  origin_ = origin;
  for (auto& [name, c] : children_) c.setOrigin(origin);
}

bool StateRecord::isTable() const {
  const auto it = fields_.find("id");
  return it != fields_.end() && it->second.type == StateField::Type::Int64 && it->second.shape.size() == 1;
}

std::size_t StateRecord::rows() const { return isTable() ? fields_.at("id").shape[0] : 0; }

namespace {

// The rows `order` of a column whose first dimension is the row count.
StateField pickRows(const StateField& f, const std::vector<std::size_t>& order) {
  StateField out = f;
  const std::size_t width = f.shape.empty() || f.shape[0] == 0 ? 0 : f.count() / f.shape[0];
  for (std::size_t r = 0; r < order.size(); ++r)
    for (std::size_t j = 0; j < width; ++j) {
      if (f.type == StateField::Type::Double) out.doubles[r * width + j] = f.doubles[order[r] * width + j];
      if (f.type == StateField::Type::Int64) out.integers[r * width + j] = f.integers[order[r] * width + j];
    }
  return out;
}

}  // namespace

void StateRecord::merge(const StateRecord& other) {
  const bool tables = isTable() && other.isTable();
  for (const auto& [name, f] : other.fields_) {
    auto it = fields_.find(name);
    if (it == fields_.end()) {
      fields_[name] = f;
    } else if (tables) {
      StateField& mine = it->second;
      if (mine.type != f.type || mine.shape.size() != f.shape.size() || mine.shape.empty() ||
          !std::equal(mine.shape.begin() + 1, mine.shape.end(), f.shape.begin() + 1))
        throw std::logic_error("StateRecord::merge: column " + path_ + name + " differs in type or row shape");
      mine.shape[0] += f.shape[0];
      mine.doubles.insert(mine.doubles.end(), f.doubles.begin(), f.doubles.end());
      mine.integers.insert(mine.integers.end(), f.integers.begin(), f.integers.end());
    }
  }
  for (const auto& [name, c] : other.children_) child(name).merge(c);
}

void StateRecord::sortTables() {
  if (isTable()) {
    const auto& ids = fields_.at("id").integers;
    std::vector<std::size_t> order(ids.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&ids](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
    for (auto& [name, f] : fields_) f = pickRows(f, order);
  }
  for (auto& [name, c] : children_) c.sortTables();
}

// ---- StateReader

void StateReader::operator()(const std::string& name, std::vector<double>& v, StateValues values) {
  const auto& f = record_.field(name, StateField::Type::Double, {StateRecord::kAnyExtent});
  record_.requireFinite(name, f.doubles.data(), f.doubles.size(), values);
  v = f.doubles;
}

// ---- Tables

void StateTableWriter::beginRow(std::int64_t id) { ids_.push_back(id); }

void StateTableWriter::append(const std::string& name, const StateField& value) {
  auto [it, created] = columns_.try_emplace(name);
  StateField& column = it->second;
  if (created) {
    if (ids_.size() != 1) throw std::logic_error("StateTableWriter: column " + name + " not in every row");
    column = value;
    column.shape.insert(column.shape.begin(), 0);
  } else if (column.type != value.type || !std::equal(column.shape.begin() + 1, column.shape.end(), value.shape.begin(),
                                                      value.shape.end())) {
    throw std::logic_error("StateTableWriter: column " + name + " changes its type or shape");
  } else {
    column.doubles.insert(column.doubles.end(), value.doubles.begin(), value.doubles.end());
    column.integers.insert(column.integers.end(), value.integers.begin(), value.integers.end());
  }
  column.shape[0] = ids_.size();
}

void StateTableWriter::finish() {
  table_.put("id", ids_, {ids_.size()});
  for (auto& [name, column] : columns_) {
    if (column.shape[0] != ids_.size()) throw std::logic_error("StateTableWriter: column " + name + " not in every row");
    table_.putField(name, std::move(column));
  }
  columns_.clear();
}

StateTableReader::StateTableReader(const StateRecord& table) : table_(table) {
  ids_ = table.field("id", StateField::Type::Int64, {StateRecord::kAnyExtent}).integers;
  for (std::size_t r = 0; r < ids_.size(); ++r)
    if (!index_.emplace(ids_[r], r).second) table.fail("id", "id " + std::to_string(ids_[r]) + " appears twice");
}

void StateTableReader::seek(std::int64_t id, const std::string& what) {
  const auto it = index_.find(id);
  if (it == index_.end()) table_.fail("id", "no row for " + what);
  row_ = it->second;
}

StateRecord StateTableReader::rowRecord(const std::string& name) const {
  const StateField& column = table_.anyField(name);
  if (column.type == StateField::Type::Text || column.shape.empty() || column.shape[0] != ids_.size())
    table_.fail(name, typeName(column.type) + " " + shapeText(column.shape) + " in the file, a column of " +
                          std::to_string(ids_.size()) + " rows expected");
  StateField row;
  row.type = column.type;
  row.shape.assign(column.shape.begin() + 1, column.shape.end());
  const std::size_t width = row.count();
  if (column.type == StateField::Type::Double)
    row.doubles.assign(column.doubles.begin() + static_cast<std::ptrdiff_t>(row_ * width),
                       column.doubles.begin() + static_cast<std::ptrdiff_t>((row_ + 1) * width));
  else
    row.integers.assign(column.integers.begin() + static_cast<std::ptrdiff_t>(row_ * width),
                        column.integers.begin() + static_cast<std::ptrdiff_t>((row_ + 1) * width));
  StateRecord one;
  one.origin_ = table_.origin_;
  one.path_ = table_.path_ + "id " + std::to_string(ids_[row_]) + "/";
  one.putField(name, std::move(row));
  return one;
}

bool sameState(const StateRecord& a, const StateRecord& b) {
  if (a.fields().size() != b.fields().size() || a.children().size() != b.children().size()) return false;
  for (const auto& [name, f] : a.fields()) {
    const auto it = b.fields().find(name);
    if (it == b.fields().end()) return false;
    const StateField& g = it->second;
    if (f.type != g.type || f.shape != g.shape || f.integers != g.integers || f.text != g.text ||
        f.doubles.size() != g.doubles.size() ||
        (!f.doubles.empty() && std::memcmp(f.doubles.data(), g.doubles.data(), f.doubles.size() * sizeof(double)) != 0))
      return false;
  }
  for (const auto& [name, c] : a.children()) {
    const auto it = b.children().find(name);
    if (it == b.children().end() || !sameState(c, it->second)) return false;
  }
  return true;
}

// ---- Checksum

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ULL;
  }
  return hash;
}

std::uint64_t stateChecksum(const StateRecord& record, std::uint64_t hash) {
  // Paths from the traversal, not the records' own: a record built apart and merged in sums alike.
  struct Walk {
    static std::uint64_t sum(const StateRecord& r, const std::string& prefix, std::uint64_t h) {
      for (const auto& [name, f] : r.fields()) {
        const std::string path = prefix + name;
        h = fnv1a(path.data(), path.size(), h);
        if (f.type == StateField::Type::Double) h = fnv1a(f.doubles.data(), f.doubles.size() * sizeof(double), h);
        if (f.type == StateField::Type::Int64) h = fnv1a(f.integers.data(), f.integers.size() * sizeof(std::int64_t), h);
        if (f.type == StateField::Type::Text) h = fnv1a(f.text.data(), f.text.size(), h);
      }
      for (const auto& [name, c] : r.children()) h = sum(c, prefix + name + "/", h);
      return h;
    }
  };
  return Walk::sum(record, record.path(), hash);
}

}  // namespace contessa
