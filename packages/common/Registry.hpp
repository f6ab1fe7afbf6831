#pragma once
// One shape for the registries that create things by their deck name (docs/style.md 4: register by
// name, no central if/else): materials, elements, mesh sources, step-size methods, contact laws. A row
// names a thing, says in one line what it is (for the deck reference) and makes it; one lookup gives
// every registry the same error for a name it does not know.
#include <string>
#include <utility>
#include <vector>

#include "common/Error.hpp"

namespace contessa {

/// A registry row: the deck name, one line of documentation ("" where the name says it all), and what
/// makes the thing (a function, or a struct of functions when it also publishes parameters).
template <class Factory>
struct RegistryRow {
  std::string name;
  std::string doc;
  Factory factory;
};

/// Rows in the order the deck reference lists them. `Row` has `name` and `doc` (RegistryRow, or a row
/// with its factory's members beside them).
template <class Row>
class Registry {
 public:
  /// `kind` names what the rows make in the unknown-name error ("material model", "mesh type").
  Registry(std::string kind, std::vector<Row> rows) : kind_(std::move(kind)), rows_(std::move(rows)) {}

  const std::vector<Row>& rows() const { return rows_; }

  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& row : rows_) result.push_back(row.name);
    return result;
  }

  /// "A, B, C".
  std::string knownNames() const {
    std::string list;
    for (const auto& row : rows_) list += (list.empty() ? "" : ", ") + row.name;
    return list;
  }

  /// The row named `name`, or nullptr.
  const Row* find(const std::string& name) const {
    for (const auto& row : rows_)
      if (row.name == name) return &row;
    return nullptr;
  }

  /// The row named `name`; otherwise InputError "<parameter>: unknown <kind> '<name>' (known: A, B, C)",
  /// `parameter` being the deck path of the parameter that gave the name.
  const Row& lookup(const std::string& name, const std::string& parameter) const {
    if (const Row* row = find(name)) return *row;
    throw InputError(parameter + ": unknown " + kind_ + " '" + name + "' (known: " + knownNames() + ")");
  }

 private:
  std::string kind_;
  std::vector<Row> rows_;
};

}  // namespace contessa
