#include "deck/ParameterValidation.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/Error.hpp"
#include "common/ErrorText.hpp"
#include "deck/DeckReader.hpp"

namespace contessa::deck {
namespace {

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::vector<std::string> entryNames(const Teuchos::ParameterList& list) {
  std::vector<std::string> names;
  for (auto it = list.begin(); it != list.end(); ++it) names.push_back(list.name(it));
  return names;
}

std::string typeName(const Teuchos::ParameterEntry& entry) {
  if (entry.isList()) return "sublist";
  return entry.getAny(false).typeName();
}

std::string valueText(const Teuchos::ParameterEntry& entry) {
  std::ostringstream os;
  entry.getAny(false).print(os);
  return os.str();
}

std::string formatNumber(double v) {
  if (v >= std::numeric_limits<double>::max()) return "inf";  // a bound that means "none"
  if (v <= -std::numeric_limits<double>::max()) return "-inf";
  std::ostringstream os;
  os << v;
  return os.str();
}

// Range validators publish their bounds; turn a violation into one line naming the path.
void checkRange(const std::string& path, const Teuchos::ParameterEntry& entry) {
  auto validator = entry.validator();
  if (validator.is_null()) return;
  if (auto d = Teuchos::rcp_dynamic_cast<const Teuchos::EnhancedNumberValidator<double>>(validator); !d.is_null()) {
    const double v = Teuchos::getValue<double>(entry);
    const bool ok = std::isfinite(v) && (!d->hasMin() || v >= d->getMin()) && (!d->hasMax() || v <= d->getMax());
    if (!ok) {
      // setPositive's bound is the smallest denormal (an open bound at 0): say "> 0", not "[4.94066e-324, ...".
      const bool positive = d->hasMin() && d->getMin() == std::nextafter(0.0, 1.0);
      if (positive && !d->hasMax()) throw InputError(path + ": expected a value > 0, got " + formatNumber(v));
      std::string range = (positive ? std::string("(0") :
                           "[" + (d->hasMin() ? formatNumber(d->getMin()) : std::string("-inf"))) + ", " +
                          (d->hasMax() ? formatNumber(d->getMax()) : std::string("inf")) + "]";
      throw InputError(path + ": expected a value in " + range + ", got " + formatNumber(v));
    }
    return;
  }
  if (auto i = Teuchos::rcp_dynamic_cast<const Teuchos::EnhancedNumberValidator<int>>(validator); !i.is_null()) {
    const int v = Teuchos::getValue<int>(entry);
    if ((i->hasMin() && v < i->getMin()) || (i->hasMax() && v > i->getMax())) {
      std::string range = "[" + (i->hasMin() ? std::to_string(i->getMin()) : std::string("-inf")) + ", " +
                          (i->hasMax() ? std::to_string(i->getMax()) : std::string("inf")) + "]";
      throw InputError(path + ": expected an integer in " + range + ", got " + std::to_string(v));
    }
    return;
  }
  if (auto s = Teuchos::rcp_dynamic_cast<const Teuchos::StringValidator>(validator); !s.is_null()) {
    const auto allowed = s->validStringValues();
    requireOneOf(path, Teuchos::getValue<std::string>(entry),
                 std::vector<std::string>(allowed->begin(), allowed->end()));
    return;
  }
  // Any other validator: use its own check, keeping the first line of its message.
  try {
    validator->validate(entry, path, "");
  } catch (const std::exception& e) {
    throw InputError(path + ": " + plainMessage(e));
  }
}

// No infinite or NaN number gets past validation, whichever way it entered the list (the text of a deck
// or of --set is refused earlier, with the text as written).
void requireFinite(const std::string& path, const Teuchos::ParameterEntry& entry) {
  if (entry.isType<double>()) {
    const double v = Teuchos::getValue<double>(entry);
    requireInput(std::isfinite(v), path + ": expected a finite number, got " + formatNumber(v));
  } else if (entry.isType<Teuchos::Array<double>>()) {
    const auto& values = Teuchos::getValue<Teuchos::Array<double>>(entry);
    for (Teuchos::Array<double>::size_type i = 0; i < values.size(); ++i)
      requireInput(std::isfinite(values[i]), path + ": expected finite numbers, got " + formatNumber(values[i]) +
                                                 " (element " + std::to_string(i + 1) + ")");
  }
}

// The open sublists of `name`'s sublist: the entries "name/rest" of `openSublists`, as "rest".
std::set<std::string> openWithin(const std::set<std::string>& openSublists, const std::string& name) {
  std::set<std::string> within;
  for (const auto& path : openSublists)
    if (path.size() > name.size() + 1 && path.compare(0, name.size() + 1, name + "/") == 0)
      within.insert(path.substr(name.size() + 1));
  return within;
}

}  // namespace

std::string joinPath(const std::string& parent, const std::string& name) {
  return parent.empty() ? name : parent + "/" + name;
}

void requireOneOf(const std::string& path, const std::string& value, const std::vector<std::string>& allowed) {
  for (const auto& a : allowed)
    if (a == value) return;
  throw InputError(path + ": expected one of " + joinNames(allowed) + "; got '" + value + "'");
}

void validateAndSetDefaults(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid,
                            const std::string& path, const std::set<std::string>& openSublists) {
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string& name = deck.name(it);
    const std::string where = joinPath(path, name);
    const Teuchos::ParameterEntry& given = deck.entry(it);
    const Teuchos::ParameterEntry* expected = valid.getEntryPtr(name);
    if (expected == nullptr) {
      const auto known = entryNames(valid);
      throw InputError(where + ": unknown parameter" +
                       (known.empty() ? std::string(" (this list takes none)") : " (expected one of: " + joinNames(known) + ")"));
    }
    if (expected->isList() != given.isList()) {
      throw InputError(where + ": expected " + (expected->isList() ? std::string("a sublist") : "a parameter of type " + typeName(*expected)) +
                       ", got " + (given.isList() ? std::string("a sublist") : "a parameter"));
    }
    if (given.isList()) {
      if (openSublists.count(name) == 0)
        validateAndSetDefaults(deck.sublist(name), valid.sublist(name), where, openWithin(openSublists, name));
      continue;
    }
    const auto& expectedType = expected->getAny(false).type();
    if (given.getAny(false).type() != expectedType) {
      // Decks often write type="int" for a real number: accept it as a double.
      // --set stores new values as text, typed here; a deck's type="..." is the user's word, held to
      // the documented type (a number declared type="string" is a mistake the deck reference would show).
      const std::string declared = declaredAt(given);
      if (expectedType == typeid(double) && given.isType<int>()) {
        deck.set(name, static_cast<double>(Teuchos::getValue<int>(given)));
      } else if (!declared.empty()) {
        const std::string expectedDeckType = deckTypeOf(*expected);
        throw InputError(declared + ": " + where + ": declared type=\"" + deckTypeOf(given) + "\", expected type=\"" +
                         (expectedDeckType.empty() ? typeName(*expected) : expectedDeckType) + "\" (value '" +
                         valueText(given) + "')");
      } else {
        const ParsedValue typed = given.isType<std::string>()
                                      ? setTypedFromText(deck, name, *expected, Teuchos::getValue<std::string>(given))
                                      : ParsedValue{ValueProblem::Malformed, "", {}};
        if (typed.problem == ValueProblem::Malformed)
          throw InputError(where + ": expected type " + typeName(*expected) + ", got " + typeName(given) + " '" +
                           valueText(given) + "'");
        requireInput(typed.problem == ValueProblem::None, where + ": " + typed.message);
      }
    }
    requireFinite(where, deck.getEntry(name));
    Teuchos::ParameterEntry& checked = deck.getEntry(name);
    checked.setValidator(expected->validator());
    checkRange(where, checked);
  }
  // Defaults for what the deck leaves out (sublists too, so consumers can read them).
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (deck.isParameter(name)) continue;
    const Teuchos::ParameterEntry& entry = valid.entry(it);
    if (entry.isList()) {
      if (openSublists.count(name) == 0)
        validateAndSetDefaults(deck.sublist(name), valid.sublist(name), joinPath(path, name),
                               openWithin(openSublists, name));
      else
        deck.sublist(name);
    } else {
      deck.setEntry(name, entry);
    }
  }
}

void setNonNegative(Teuchos::ParameterList& list, const std::string& name, double value, const std::string& doc) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>());
  v->setMin(0.0);
  list.set(name, value, doc + " (>= 0)", v);
}

void setBounded(Teuchos::ParameterList& list, const std::string& name, double value, double min, double max,
                const std::string& doc) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(min, max));
  list.set(name, value, doc + " ([" + formatNumber(min) + ", " + formatNumber(max) + "])", v);
}

}  // namespace contessa::deck
