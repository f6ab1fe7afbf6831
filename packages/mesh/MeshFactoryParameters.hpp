#pragma once
// A generator's deck parameters as one table: each row names a parameter, its type and range, its
// default and its doc, and the member of the generator's spec it fills. The same rows publish the list
// the deck is validated against (and the deck reference is generated from) and read the validated list
// into the spec, so a parameter cannot be declared without being read, or read under another name,
// type or default than it was declared with.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "common/ParameterPublishing.hpp"

namespace contessa::mesh {

/// Where a row's value goes in `Spec`: a data member (`&Spec::x0`) or a function returning a reference
/// (`[](Spec& s) -> double& { return s.center[0]; }`).
template <class Spec, class T>
using SpecField = std::function<T&(Spec&)>;

template <class Spec>
class ParameterTable {
 public:
  /// `listName`: the name of the list publish() makes ("" for a table only included in others).
  explicit ParameterTable(std::string listName = "") : listName_(std::move(listName)) {}

  /// Where a table of this spec sits in an `Outer` spec (include's argument; not deduced from it).
  template <class Outer>
  using Within = SpecField<Outer, Spec>;

  /// A real number of either sign.
  ParameterTable& real(const std::string& name, SpecField<Spec, double> field, double value, const std::string& doc) {
    return add(name, std::move(field), [=](Teuchos::ParameterList& p) { p.set(name, value, doc); });
  }
  /// A real number > 0 (setPositive).
  ParameterTable& positive(const std::string& name, SpecField<Spec, double> field, double value,
                           const std::string& doc) {
    return add(name, std::move(field), [=](Teuchos::ParameterList& p) { setPositive(p, name, value, doc); });
  }
  /// A whole number >= 1 (setPositiveInt).
  ParameterTable& count(const std::string& name, SpecField<Spec, int> field, int value, const std::string& doc) {
    return add(name, std::move(field), [=](Teuchos::ParameterList& p) { setPositiveInt(p, name, value, doc); });
  }
  /// Any text.
  ParameterTable& text(const std::string& name, SpecField<Spec, std::string> field, const std::string& value,
                       const std::string& doc) {
    return add(name, std::move(field), [=](Teuchos::ParameterList& p) { p.set(name, value, doc); });
  }
  /// One of `choices` (setChoice).
  ParameterTable& choice(const std::string& name, SpecField<Spec, std::string> field, const std::string& value,
                         const std::vector<std::string>& choices, const std::string& doc) {
    return add(name, std::move(field),
               [=](Teuchos::ParameterList& p) { setChoice(p, name, value, choices, doc); });
  }

  /// The rows of `part`'s table, filling `field` of the spec (a generator built on another one's spec).
  template <class Part>
  ParameterTable& include(const ParameterTable<Part>& part, typename ParameterTable<Part>::template Within<Spec> field) {
    for (const auto& row : part.rows_)
      rows_.push_back({row.publish, [read = row.read, field](const Teuchos::ParameterList& p, Spec& s) {
                         read(p, field(s));
                       }});
    return *this;
  }

  /// The rows of another table of the same spec (parameters several generators share).
  ParameterTable& include(const ParameterTable& rows) {
    rows_.insert(rows_.end(), rows.rows_.begin(), rows.rows_.end());
    return *this;
  }

  /// The parameters, in the rows' order, with their defaults, docs and validators.
  Teuchos::RCP<Teuchos::ParameterList> publish() const {
    auto list = Teuchos::rcp(new Teuchos::ParameterList(listName_));
    for (const auto& row : rows_) row.publish(*list);
    return list;
  }

  /// The spec a list validated against publish() gives.
  Spec read(const Teuchos::ParameterList& list) const {
    Spec spec;
    for (const auto& row : rows_) row.read(list, spec);
    return spec;
  }

 private:
  template <class U>
  friend class ParameterTable;

  struct Row {
    std::function<void(Teuchos::ParameterList&)> publish;
    std::function<void(const Teuchos::ParameterList&, Spec&)> read;
  };

  template <class T>
  ParameterTable& add(const std::string& name, SpecField<Spec, T> field,
                      std::function<void(Teuchos::ParameterList&)> publish) {
    rows_.push_back({std::move(publish), [name, field = std::move(field)](const Teuchos::ParameterList& p, Spec& s) {
                       field(s) = p.get<T>(name);
                     }});
    return *this;
  }

  std::string listName_;
  std::vector<Row> rows_;
};

}  // namespace contessa::mesh
