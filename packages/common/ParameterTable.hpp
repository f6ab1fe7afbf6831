#pragma once
// A configurable class's deck parameters as one table (docs/style.md 5): each row names a parameter, its
// default, its doc (and range), and the member of the class's spec it fills. The same rows publish the
// list the deck is validated against (and the deck reference is generated from) and read the validated
// list into the spec, so a parameter cannot be declared without being read, or read under another name,
// type or default than it was declared with. Used by the mesh generators and files, the contact
// interfaces and Contact Beta.
#include <algorithm>
#include <functional>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "common/ParameterPublishing.hpp"

namespace contessa {

/// Where a row's value goes in `Spec`: a data member (`&Spec::x0`) or a function returning a reference
/// (`[](Spec& s) -> double& { return s.center[0]; }`).
template <class Spec, class T>
using SpecField = std::function<T&(Spec&)>;

/// `T` where a row's type is taken from its default value only (a member pointer or a function converts).
template <class T>
using FromDefault = typename std::common_type<T>::type;

template <class Spec>
class ParameterTable {
 public:
  /// Publishes one parameter: `declare(list, name, value, doc)` (Teuchos' set with a validator, e.g.
  /// setPositive).
  template <class T>
  using Declare = std::function<void(Teuchos::ParameterList&, const std::string&, const T&, const std::string&)>;

  /// `listName`: the name of the list publish() makes ("" for a table only included in others).
  explicit ParameterTable(std::string listName = "") : listName_(std::move(listName)) {}

  /// Where a table of this spec sits in an `Outer` spec (include's argument; not deduced from it).
  template <class Outer>
  using Within = SpecField<Outer, Spec>;

  /// A value of any type the list holds (a real of either sign, text, a flag, an array), without a range.
  template <class T>
  ParameterTable& value(const std::string& name, FromDefault<SpecField<Spec, T>> field, const T& value,
                        const std::string& doc) {
    return declared<T>(name, std::move(field), value, doc, plainSet<T>);
  }
  /// A value published by `declare` (a range of its own), read as it was declared.
  template <class T>
  ParameterTable& declared(const std::string& name, FromDefault<SpecField<Spec, T>> field, const T& value,
                           const std::string& doc, FromDefault<Declare<T>> declare) {
    rows_.push_back({[=](Teuchos::ParameterList& p) { declare(p, name, value, doc); },
                     [name, field = std::move(field)](const Teuchos::ParameterList& p, Spec& s) {
                       field(s) = p.get<T>(name);
                     }});
    return *this;
  }

  ParameterTable& real(const std::string& name, SpecField<Spec, double> field, double v, const std::string& doc) {
    return value<double>(name, std::move(field), v, doc);
  }
  ParameterTable& text(const std::string& name, SpecField<Spec, std::string> field, const std::string& v,
                       const std::string& doc) {
    return value<std::string>(name, std::move(field), v, doc);
  }
  /// A real number > 0 (setPositive).
  ParameterTable& positive(const std::string& name, SpecField<Spec, double> field, double v, const std::string& doc) {
    return declared<double>(name, std::move(field), v, doc, setPositive);
  }
  /// A whole number >= 1 (setPositiveInt).
  ParameterTable& count(const std::string& name, SpecField<Spec, int> field, int v, const std::string& doc) {
    return declared<int>(name, std::move(field), v, doc, setPositiveInt);
  }
  /// One of `choices` (setChoice), read as the name.
  ParameterTable& choice(const std::string& name, SpecField<Spec, std::string> field, const std::string& v,
                         const std::vector<std::string>& choices, const std::string& doc) {
    return declared<std::string>(name, std::move(field), v, doc, choiceOf(choices));
  }
  /// One of `names`, listed in the order of Enum's values (setChoice), read as the value.
  template <class Enum>
  ParameterTable& enumChoice(const std::string& name, FromDefault<SpecField<Spec, Enum>> field, Enum v,
                         const std::vector<std::string>& names, const std::string& doc) {
    rows_.push_back({[=](Teuchos::ParameterList& p) { setChoice(p, name, names.at(static_cast<std::size_t>(v)), names, doc); },
                     [=](const Teuchos::ParameterList& p, Spec& s) {
                       const auto it = std::find(names.begin(), names.end(), p.get<std::string>(name));
                       field(s) = static_cast<Enum>(it - names.begin());  // validated: one of names
                     }});
    return *this;
  }

  /// A sublist `name` (with its doc) holding `part`'s rows, read into `field` of the spec.
  template <class Part>
  ParameterTable& sublist(const std::string& name, const std::string& doc, const ParameterTable<Part>& part,
                          typename ParameterTable<Part>::template Within<Spec> field) {
    rows_.push_back({[=](Teuchos::ParameterList& p) { part.publishInto(p.sublist(name, false, doc)); },
                     [=](const Teuchos::ParameterList& p, Spec& s) { part.readInto(p.sublist(name), field(s)); }});
    return *this;
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

  /// The rows of another table of the same spec (parameters several specs share).
  ParameterTable& include(const ParameterTable& rows) {
    rows_.insert(rows_.end(), rows.rows_.begin(), rows.rows_.end());
    return *this;
  }

  /// The parameters, in the rows' order, with their defaults, docs and validators.
  Teuchos::RCP<Teuchos::ParameterList> publish() const {
    auto list = Teuchos::rcp(new Teuchos::ParameterList(listName_));
    publishInto(*list);
    return list;
  }
  /// The same rows added to `list` (a list that others publish into too).
  void publishInto(Teuchos::ParameterList& list) const {
    for (const auto& row : rows_) row.publish(list);
  }

  /// The spec a list validated against publish() gives (members without a row: the spec's defaults).
  Spec read(const Teuchos::ParameterList& list) const {
    Spec spec{};
    readInto(list, spec);
    return spec;
  }
  void readInto(const Teuchos::ParameterList& list, Spec& spec) const {
    for (const auto& row : rows_) row.read(list, spec);
  }

 private:
  template <class U>
  friend class ParameterTable;

  struct Row {
    std::function<void(Teuchos::ParameterList&)> publish;
    std::function<void(const Teuchos::ParameterList&, Spec&)> read;
  };

  template <class T>
  static void plainSet(Teuchos::ParameterList& p, const std::string& name, const T& v, const std::string& doc) {
    p.set(name, v, doc);
  }
  static Declare<std::string> choiceOf(const std::vector<std::string>& choices) {
    return [choices](Teuchos::ParameterList& p, const std::string& name, const std::string& v, const std::string& doc) {
      setChoice(p, name, v, choices, doc);
    };
  }

  std::string listName_;
  std::vector<Row> rows_;
};

}  // namespace contessa
