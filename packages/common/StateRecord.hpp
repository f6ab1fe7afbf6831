#pragma once
// A restart file's state, by name (docs/architecture.md, "Checkpoint and restart"): a tree of records,
// each holding named fields (typed values with their shape) and named child records. A class that keeps
// state across a restart declares its fields once, next to its members, in a template function that
// both saving (StateWriter) and loading (StateReader) run:
//
//   template <class Self, class Fields> static void stateFields(Self& self, Fields& field) {
//     field("lambda", self.lambda_);
//     field("gap", self.gap_, StateValues::AnyDouble);  // may be ±inf or NaN
//   }
//   void saveState(StateRecord& r) const { StateWriter w(r); stateFields(*this, w); }
//   void loadState(const StateRecord& r) { StateReader in(r); stateFields(*this, in); }
//
// Adding a member to the restart is then one line. Loading names what does not fit in one line,
// "<origin>: <path>: ...": a missing field, one of another type or shape, a value that is not finite
// (unless declared AnyDouble), and, after everything is loaded, a field nobody read (firstUnread).
// Rows of many entities (nodes, elements, slave nodes) are tables: a record with an "id" column (int64,
// one per row) and columns whose first dimension is the row count (StateTableWriter, StateTableReader).
// Pure C++: the file format is io/RestartFile's.
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace contessa {

/// Values a double field may take: finite only (the default), or any (±inf and NaN are meaningful).
enum class StateValues { Finite, AnyDouble };

/// One named field: values with their shape (row-major; {} is a scalar).
struct StateField {
  enum class Type { Double, Int64, Text };
  Type type = Type::Double;
  std::vector<std::size_t> shape;
  std::vector<double> doubles;        ///< Type::Double
  std::vector<std::int64_t> integers; ///< Type::Int64
  std::string text;                   ///< Type::Text (shape {})
  std::size_t count() const;          ///< the product of the shape
};

std::string typeName(StateField::Type type);
/// "[]", "[3]", "[1428, 2]".
std::string shapeText(const std::vector<std::size_t>& shape);

class StateRecord {
 public:
  // ---- Writing.
  void put(const std::string& name, std::vector<double> values, std::vector<std::size_t> shape);
  void put(const std::string& name, std::vector<std::int64_t> values, std::vector<std::size_t> shape);
  void putText(const std::string& name, std::string text);
  void putField(const std::string& name, StateField field);
  /// The child `name`, created when missing.
  StateRecord& child(const std::string& name);

  // ---- Reading: InputError "<origin>: <path>: ..." when the field is missing or of another type or
  // shape. Every read marks the field as known (firstUnread).
  /// The field `name` of `type`; `shape` entries kAnyExtent match any length.
  static constexpr std::size_t kAnyExtent = static_cast<std::size_t>(-1);
  const StateField& field(const std::string& name, StateField::Type type, const std::vector<std::size_t>& shape) const;
  double getDouble(const std::string& name, StateValues values = StateValues::Finite) const;
  std::int64_t getInt(const std::string& name) const;
  const std::string& getText(const std::string& name) const;
  /// The child `name`; InputError when missing.
  const StateRecord& child(const std::string& name) const;
  /// A child its owner reads later and checks itself (requireAllRead): firstUnread skips it.
  const StateRecord& claim(const std::string& name) const;
  bool has(const std::string& name) const { return fields_.count(name) != 0; }
  bool hasChild(const std::string& name) const { return children_.count(name) != 0; }
  /// The field `name` whatever its type and shape (marked read); InputError when missing.
  const StateField& anyField(const std::string& name) const;
  /// Throws InputError "<origin>: <path><name>: <what>".
  [[noreturn]] void fail(const std::string& name, const std::string& what) const;
  /// InputError when a double value of `values` is not finite, naming the field and the flat index.
  void requireFinite(const std::string& name, const double* values, std::size_t n, StateValues allowed) const;

  /// The first field (its path) that no one read, in this record and its children not claimed; "" if none.
  std::string firstUnread() const;
  /// InputError "<origin>: <path>: unknown field (not read by this Contessa)" for the first unread field.
  void requireAllRead() const;

  // ---- Structure.
  const std::map<std::string, StateField>& fields() const { return fields_; }
  const std::map<std::string, StateRecord>& children() const { return children_; }
  /// Where errors say the record comes from ("--restart out/tube.restart"), here and in every child.
  void setOrigin(const std::string& origin);
  const std::string& origin() const { return origin_; }
  /// "" at the root, "contact/interface_0/" below.
  const std::string& path() const { return path_; }
  /// Adds `other`'s fields and children: a field this record lacks is copied; a table (a record with an
  /// "id" column) present in both gets other's rows appended. Other fields present in both stay as here.
  void merge(const StateRecord& other);
  /// Sorts the rows of every table in the tree by id (a file independent of the rank count).
  void sortTables();
  /// Is this record a table: an "id" column of int64 with one entry per row.
  bool isTable() const;
  std::size_t rows() const;  ///< a table's row count

 private:
  std::map<std::string, StateField> fields_;
  std::map<std::string, StateRecord> children_;
  std::string path_, origin_;
  mutable std::set<std::string> read_;
  mutable bool claimed_ = false;
  friend class StateTableReader;
};

// ---- Declaring fields: one function, run by both visitors.

/// Saves the fields a class declares into a record (shape {} for scalars, {N} for arrays and vectors).
class StateWriter {
 public:
  explicit StateWriter(StateRecord& record) : record_(record) {}
  void operator()(const std::string& name, double v, StateValues = StateValues::Finite) { record_.put(name, std::vector<double>{v}, {}); }
  void operator()(const std::string& name, const std::vector<double>& v, StateValues = StateValues::Finite) {
    record_.put(name, v, {v.size()});
  }
  template <std::size_t N>
  void operator()(const std::string& name, const std::array<double, N>& v, StateValues = StateValues::Finite) {
    record_.put(name, std::vector<double>(v.begin(), v.end()), {N});
  }
  template <std::size_t M, std::size_t N>
  void operator()(const std::string& name, const std::array<std::array<double, N>, M>& v,
                  StateValues = StateValues::Finite) {
    std::vector<double> flat;
    for (const auto& row : v) flat.insert(flat.end(), row.begin(), row.end());
    record_.put(name, std::move(flat), {M, N});
  }
  template <std::size_t N>
  void operator()(const std::string& name, const std::array<int, N>& v) {
    record_.put(name, std::vector<std::int64_t>(v.begin(), v.end()), {N});
  }
  void operator()(const std::string& name, const std::string& v) { record_.putText(name, v); }
  /// Integers, bools and enums: int64.
  template <class T, class = std::enable_if_t<std::is_integral_v<T> || std::is_enum_v<T>>>
  void operator()(const std::string& name, T v) {
    record_.put(name, std::vector<std::int64_t>{static_cast<std::int64_t>(v)}, {});
  }

 private:
  StateRecord& record_;
};

/// Loads the fields a class declares from a record: each must be there with its type and shape (a
/// std::vector any length), its doubles finite unless declared AnyDouble.
class StateReader {
 public:
  explicit StateReader(const StateRecord& record) : record_(record) {}
  void operator()(const std::string& name, double& v, StateValues values = StateValues::Finite) {
    v = record_.getDouble(name, values);
  }
  void operator()(const std::string& name, std::vector<double>& v, StateValues values = StateValues::Finite);
  template <std::size_t N>
  void operator()(const std::string& name, std::array<double, N>& v, StateValues values = StateValues::Finite) {
    const auto& f = record_.field(name, StateField::Type::Double, {N});
    record_.requireFinite(name, f.doubles.data(), N, values);
    for (std::size_t i = 0; i < N; ++i) v[i] = f.doubles[i];
  }
  template <std::size_t M, std::size_t N>
  void operator()(const std::string& name, std::array<std::array<double, N>, M>& v,
                  StateValues values = StateValues::Finite) {
    const auto& f = record_.field(name, StateField::Type::Double, {M, N});
    record_.requireFinite(name, f.doubles.data(), M * N, values);
    for (std::size_t i = 0; i < M; ++i)
      for (std::size_t j = 0; j < N; ++j) v[i][j] = f.doubles[i * N + j];
  }
  template <std::size_t N>
  void operator()(const std::string& name, std::array<int, N>& v) {
    const auto& f = record_.field(name, StateField::Type::Int64, {N});
    for (std::size_t i = 0; i < N; ++i) v[i] = static_cast<int>(f.integers[i]);
  }
  void operator()(const std::string& name, std::string& v) { v = record_.getText(name); }
  template <class T, class = std::enable_if_t<std::is_integral_v<T> || std::is_enum_v<T>>>
  void operator()(const std::string& name, T& v) {
    const std::int64_t i = record_.getInt(name);
    if constexpr (std::is_same_v<T, bool>)
      v = i != 0;
    else
      v = static_cast<T>(i);
  }

 private:
  const StateRecord& record_;
};

/// Rows of a table: beginRow(id), then the row's fields through operator() as StateWriter's; every row
/// must declare the same fields with the same shapes. finish() stores the columns ({rows, ...}).
class StateTableWriter {
 public:
  explicit StateTableWriter(StateRecord& table) : table_(table) {}
  void beginRow(std::int64_t id);
  template <class... T>
  void operator()(const std::string& name, const T&... v) {
    StateRecord one;
    StateWriter w(one);
    w(name, v...);
    append(name, one.fields().at(name));
  }
  void finish();

 private:
  void append(const std::string& name, const StateField& value);
  StateRecord& table_;
  std::vector<std::int64_t> ids_;
  std::map<std::string, StateField> columns_;
};

/// One row of a table, by id, read as StateReader reads a record.
class StateTableReader {
 public:
  /// InputError unless `table` is a table ("id" column, unique ids).
  explicit StateTableReader(const StateRecord& table);
  std::size_t rows() const { return ids_.size(); }
  std::int64_t idAt(std::size_t row) const { return ids_[row]; }
  bool hasRow(std::int64_t id) const { return index_.count(id) != 0; }
  /// Reads row `id` next; InputError "<origin>: <path>: no row for <what>" when missing.
  void seek(std::int64_t id, const std::string& what);
  void seekRow(std::size_t row) { row_ = row; }
  /// As StateReader's, for the current row (`extra`: a StateValues for doubles).
  template <class T, class... Extra>
  void operator()(const std::string& name, T& v, Extra... extra) {
    const StateRecord one = rowRecord(name);
    StateReader in(one);
    in(name, v, extra...);
  }

 private:
  /// A record holding only the current row of column `name` (its errors name the table and the row).
  StateRecord rowRecord(const std::string& name) const;
  const StateRecord& table_;
  std::vector<std::int64_t> ids_;
  std::map<std::int64_t, std::size_t> index_;
  std::size_t row_ = 0;
};

/// The same fields and children, with the same types, shapes and values (doubles bit for bit).
bool sameState(const StateRecord& a, const StateRecord& b);

/// 64-bit FNV-1a, continued from `hash`.
std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash = 14695981039346656037ULL);
/// The tree's checksum, continued from `hash`: for every field, fields before children, each in name
/// order, the FNV-1a of its path ("contact/interface_0/slaves/xi") and then of its values' bytes (native
/// doubles and int64, text as is). docs/user-guide.md, "Checkpoint and restart", gives it for tools.
std::uint64_t stateChecksum(const StateRecord& record, std::uint64_t hash = 14695981039346656037ULL);

}  // namespace contessa
