#include "deck/DeckReader.hpp"

#include <cerrno>
#include <cstdlib>
#include <fstream>

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

}  // namespace

bool setTypedFromText(Teuchos::ParameterList& list, const std::string& name, const Teuchos::ParameterEntry& typed,
                      const std::string& text) {
  return setTypedImpl(list, name, typed, text);
}

Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path) {
  std::ifstream probe(path);
  requireInput(probe.good(), path + ": cannot open deck file");
  try {
    return Teuchos::getParametersFromXmlFile(path);
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
