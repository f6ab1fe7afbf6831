#include "deck/ValueText.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <Teuchos_Array.hpp>

namespace contessa::deck {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\n\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\n\r") - first + 1);
}

ParsedValue refused(ValueProblem problem, const std::string& message) {
  ParsedValue p;
  p.problem = problem;
  p.message = message;
  return p;
}

// A decimal number: strtod alone would also take "inf", "nan(...)" and hexadecimal "0x1p3", which
// no deck means to write; the first two are named as what they are.
ParsedValue parseDouble(const std::string& text, double& value) {
  const std::string t = trimmed(text);
  const auto bad = [&] { return refused(ValueProblem::Malformed, "'" + t + "' is not a valid double"); };
  if (t.empty()) return bad();
  errno = 0;
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  const bool overflow = errno == ERANGE && std::abs(value) == HUGE_VAL;
  if (*end != '\0') return bad();
  if (!std::isfinite(value) || overflow)
    return refused(ValueProblem::NotFinite,
                   "'" + t + "' is not a finite number" + (overflow ? " (too large for a double)" : ""));
  if (t.find_first_not_of("0123456789+-.eE") != std::string::npos) return bad();  // hexadecimal
  // errno == ERANGE without overflow is an underflow: the value rounds to 0 or a subnormal number.
  return {};
}

ParsedValue parseInt(const std::string& text, int& value) {
  const std::string t = trimmed(text);
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (t.empty() || *end != '\0') return refused(ValueProblem::Malformed, "'" + t + "' is not a valid int");
  if (errno == ERANGE || v < INT32_MIN || v > INT32_MAX)
    return refused(ValueProblem::OutOfRange, "'" + t + "' is out of the range of an int");
  value = static_cast<int>(v);
  return {};
}

ParsedValue parseBool(const std::string& text, bool& value) {
  const std::string t = trimmed(text);
  if (t == "true" || t == "True" || t == "TRUE" || t == "1") value = true;
  else if (t == "false" || t == "False" || t == "FALSE" || t == "0") value = false;
  else return refused(ValueProblem::Malformed, "'" + t + "' is not a valid bool (expected true or false)");
  return {};
}

ParsedValue parseScalar(const std::string& type, const std::string& text, std::string* s, double* d, int* i, bool* b) {
  if (type == "string") { *s = text; return {}; }
  if (type == "double") return parseDouble(text, *d);
  if (type == "int") return parseInt(text, *i);
  return parseBool(text, *b);
}

// "{a, b, ...}" split at commas; an element is trimmed and may not be empty.
ParsedValue parseArray(const std::string& element, const std::string& text, bool bracesOptional) {
  std::string t = trimmed(text);
  const bool braced = t.size() >= 2 && t.front() == '{' && t.back() == '}';
  if (!braced && !(bracesOptional && t.find_first_of("{}") == std::string::npos))
    return refused(ValueProblem::Malformed, "expected an array {a, b, ...}, got '" + t + "'");
  if (braced) t = trimmed(t.substr(1, t.size() - 2));
  std::vector<std::string> items;
  for (std::size_t start = 0; !t.empty();) {
    const auto comma = t.find(',', start);
    items.push_back(trimmed(t.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  Teuchos::Array<std::string> strings;
  Teuchos::Array<double> doubles;
  Teuchos::Array<int> ints;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::string where = "element " + std::to_string(k + 1) + " of " + "{" + t + "}: ";
    if (items[k].empty()) return refused(ValueProblem::Malformed, where + "empty (a stray comma?)");
    std::string s;
    double d = 0;
    int i = 0;
    bool b = false;
    ParsedValue p = parseScalar(element, items[k], &s, &d, &i, &b);
    if (p.problem != ValueProblem::None) return refused(p.problem, where + p.message);
    strings.push_back(s);
    doubles.push_back(d);
    ints.push_back(i);
  }
  ParsedValue p;
  if (element == "string") p.entry.setValue(strings);
  else if (element == "double") p.entry.setValue(doubles);
  else p.entry.setValue(ints);
  return p;
}

}  // namespace

const std::vector<std::string>& deckTypes() {
  static const std::vector<std::string> types = {"string", "double", "int", "bool",
                                                 "Array(string)", "Array(double)", "Array(int)"};
  return types;
}

std::string deckTypeOf(const Teuchos::ParameterEntry& entry) {
  if (entry.isList()) return "";
  if (entry.isType<std::string>()) return "string";
  if (entry.isType<double>()) return "double";
  if (entry.isType<int>()) return "int";
  if (entry.isType<bool>()) return "bool";
  if (entry.isType<Teuchos::Array<std::string>>()) return "Array(string)";
  if (entry.isType<Teuchos::Array<double>>()) return "Array(double)";
  if (entry.isType<Teuchos::Array<int>>()) return "Array(int)";
  return "";
}

ParsedValue parseValue(const std::string& type, const std::string& text, bool bracesOptional) {
  const auto& types = deckTypes();
  if (std::find(types.begin(), types.end(), type) == types.end())
    return refused(ValueProblem::Malformed, "'" + type + "' is not a deck type");
  if (type.rfind("Array(", 0) == 0) return parseArray(type.substr(6, type.size() - 7), text, bracesOptional);
  std::string s;
  double d = 0;
  int i = 0;
  bool b = false;
  ParsedValue p = parseScalar(type, text, &s, &d, &i, &b);
  if (p.problem != ValueProblem::None) return p;
  if (type == "string") p.entry.setValue(s);
  else if (type == "double") p.entry.setValue(d);
  else if (type == "int") p.entry.setValue(i);
  else p.entry.setValue(b);
  return p;
}

}  // namespace contessa::deck
