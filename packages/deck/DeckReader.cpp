#include "deck/DeckReader.hpp"

#include <cerrno>
#include <cstdlib>
#include <fstream>

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include "common/Error.hpp"
#include "deck/ParameterValidation.hpp"

namespace contessa::deck {
namespace {

std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  while (true) {
    const auto slash = path.find('/', start);
    parts.push_back(path.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return parts;
}

bool parseBool(const std::string& text, bool& value) {
  if (text == "true" || text == "True" || text == "TRUE" || text == "1") { value = true; return true; }
  if (text == "false" || text == "False" || text == "FALSE" || text == "0") { value = false; return true; }
  return false;
}

bool parseInt(const std::string& text, int& value) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < INT32_MIN || v > INT32_MAX) return false;
  value = static_cast<int>(v);
  return true;
}

bool parseDouble(const std::string& text, double& value) {
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && errno == 0;
}

bool setTypedImpl(Teuchos::ParameterList& list, const std::string& name, const Teuchos::ParameterEntry& typed,
              const std::string& text) {
  if (typed.isType<std::string>()) { list.set(name, text); return true; }
  if (typed.isType<double>()) { double v; if (!parseDouble(text, v)) return false; list.set(name, v); return true; }
  if (typed.isType<int>()) { int v; if (!parseInt(text, v)) return false; list.set(name, v); return true; }
  if (typed.isType<bool>()) { bool v; if (!parseBool(text, v)) return false; list.set(name, v); return true; }
  return false;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\n\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\n\r") - first + 1);
}

// Teuchos reads numbers with a stream and keeps whatever prefix parses ("abc" → 0, "1e-2x" → 0.01):
// every numeric and boolean value of the deck is checked here first, so a typo is an error.
void checkValueTexts(const Teuchos::XMLObject& node, const std::string& where, const std::string& path) {
  if (node.getTag() == "ParameterList") {
    const std::string name = node.hasAttribute("name") ? node.getAttribute("name") : "";
    for (int i = 0; i < node.numChildren(); ++i) checkValueTexts(node.getChild(i), joinPath(where, name), path);
    return;
  }
  if (node.getTag() != "Parameter" || !node.hasAttribute("type") || !node.hasAttribute("value")) return;
  const std::string type = node.getAttribute("type");
  const std::string name = node.hasAttribute("name") ? node.getAttribute("name") : "?";
  const std::string paramPath = joinPath(where, name);
  std::vector<std::string> items;
  std::string text = node.getAttribute("value");
  std::string element = type;
  if (type.rfind("Array(", 0) == 0) {
    element = type.substr(6, type.size() - 7);
    text = trimmed(text);
    requireInput(text.size() >= 2 && text.front() == '{' && text.back() == '}',
                 path + ": " + paramPath + ": expected an array {a, b, ...}, got '" + text + "'");
    std::string inner = text.substr(1, text.size() - 2);
    std::size_t start = 0;
    while (!trimmed(inner).empty()) {
      const auto comma = inner.find(',', start);
      items.push_back(trimmed(inner.substr(start, comma - start)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  } else {
    items.push_back(trimmed(text));
  }
  for (const auto& item : items) {
    bool ok = true;
    if (element == "double") { double v; ok = parseDouble(item, v); }
    else if (element == "int") { int v; ok = parseInt(item, v); }
    else if (element == "bool") { bool v; ok = parseBool(item, v); }
    requireInput(ok, path + ": " + paramPath + ": '" + item + "' is not a valid " + element);
  }
}

}  // namespace

bool setTypedFromText(Teuchos::ParameterList& list, const std::string& name, const Teuchos::ParameterEntry& typed,
                      const std::string& text) {
  return setTypedImpl(list, name, typed, text);
}

Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path) {
  std::ifstream probe(path);
  requireInput(probe.good(), path + ": cannot open deck file");
  try {
    const auto root = Teuchos::FileInputSource(path).getObject();
    for (int i = 0; i < root.numChildren(); ++i) checkValueTexts(root.getChild(i), "", path);
    return Teuchos::getParametersFromXmlFile(path);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    std::string msg = e.what();
    // Teuchos' messages run over several lines; keep the gist on one.
    for (auto& c : msg)
      if (c == '\n') c = ' ';
    if (msg.size() > 300) msg = msg.substr(0, 300) + "...";
    throw InputError(path + ": not a valid XML parameter list (" + msg + ")");
  }
}

std::set<std::string> applyOverrides(Teuchos::ParameterList& deck, const std::vector<std::string>& overrides) {
  std::set<std::string> paths;
  for (const auto& item : overrides) {
    const auto eq = item.find('=');
    requireInput(eq != std::string::npos && eq > 0, "--set " + item + ": expected PATH=VALUE");
    const std::string path = item.substr(0, eq);
    const std::string value = item.substr(eq + 1);
    const auto parts = splitPath(path);
    Teuchos::ParameterList* list = &deck;
    std::string where;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      where = joinPath(where, parts[i]);
      requireInput(!parts[i].empty(), "--set " + item + ": empty name in the path");
      requireInput(!list->isParameter(parts[i]) || list->isSublist(parts[i]),
                   "--set " + item + ": '" + where + "' is a parameter, not a sublist");
      list = &list->sublist(parts[i]);
    }
    const std::string& name = parts.back();
    requireInput(!name.empty(), "--set " + item + ": empty parameter name");
    requireInput(!list->isSublist(name), "--set " + item + ": '" + path + "' is a sublist, not a parameter");
    if (list->isParameter(name)) {
      const Teuchos::ParameterEntry typed = list->getEntry(name);
      requireInput(setTypedFromText(*list, name, typed, value),
                   "--set " + item + ": '" + value + "' is not a valid " + typed.getAny(false).typeName());
    } else {
      list->set(name, value);
    }
    paths.insert(path);
  }
  return paths;
}

}  // namespace contessa::deck
