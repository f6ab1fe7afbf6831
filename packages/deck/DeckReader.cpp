#include "deck/DeckReader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "common/Error.hpp"
#include "deck/ParameterValidation.hpp"
#include "deck/XmlDocument.hpp"

namespace contessa::deck {
namespace {

// A deck is a few kilobytes; anything this large is another kind of file given by mistake.
constexpr std::size_t kMaxDeckBytes = 64u << 20;

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

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The XML tree of a deck turned into a ParameterList, with the line of each element for messages.
// Teuchos' own reader would accept attributes it ignores, types a deck cannot mean (float), numbers
// it reads by prefix ("1e-2x" as 0.01, "0x10" as 0) and the last of two equal names.
class DeckBuilder {
 public:
  explicit DeckBuilder(std::string file) : file_(std::move(file)) {}

  void fill(const XmlElement& list, const std::string& path, Teuchos::ParameterList& out) const {
    checkAttributes(list, {"name"}, "name");
    if (list.textLine > 0)
      fail(list.textLine, "text inside " + list.describe() + " (values go in <Parameter name=\"...\" type=\"...\" value=\"...\"/>)");
    std::map<std::string, int> seen;  // name → line, in this list
    for (const auto& child : list.children) {
      const bool isList = child.tag == "ParameterList";
      if (!isList && child.tag != "Parameter")
        fail(child.line, "unknown element <" + child.tag + "> in " + where(path) +
                             " (a ParameterList holds <Parameter> and <ParameterList> elements)");
      if (!isList) checkAttributes(child, {"name", "type", "value"}, "name, type, value");
      const std::string* name = child.attribute("name");
      if (name == nullptr || name->empty())
        fail(child.line, "<" + child.tag + "> without a name in " + where(path) + " (expected name=\"...\")");
      const std::string childPath = joinPath(path, *name);
      if (const auto [it, inserted] = seen.emplace(*name, child.line); !inserted)
        fail(child.line, childPath + ": given twice in one list (lines " + std::to_string(it->second) + " and " +
                             std::to_string(child.line) + "); keep one");
      if (isList) fill(child, childPath, out.sublist(*name));
      else parameter(child, childPath, *name, out);
    }
  }

 private:
  std::string file_;

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(line) + ": " + what);
  }
  static std::string where(const std::string& path) { return path.empty() ? "the top-level list" : path; }

  void checkAttributes(const XmlElement& e, const std::vector<std::string>& allowed, const std::string& expected) const {
    for (const auto& [key, value] : e.attributes) {
      // id, isUsed, isDefault and docString are written by Teuchos' own XML writer; they carry nothing here.
      bool known = key == "id" || key == "isUsed" || key == "isDefault" || key == "docString";
      for (const auto& a : allowed) known = known || key == a;
      if (!known) fail(e.line, "unknown attribute '" + key + "' in " + e.describe() + " (expected " + expected + ")");
    }
  }

  void parameter(const XmlElement& p, const std::string& path, const std::string& name, Teuchos::ParameterList& out) const {
    if (!p.children.empty() || p.textLine > 0)
      fail(p.line, path + ": a Parameter holds no text or elements; give the value as value=\"...\" and end the tag with '/>'");
    const std::string* type = p.attribute("type");
    const std::string* value = p.attribute("value");
    if (type == nullptr) fail(p.line, path + ": <Parameter> without a type (e.g. type=\"double\")");
    if (value == nullptr) fail(p.line, path + ": <Parameter> without a value (expected value=\"...\")");
    const auto& types = deckTypes();
    if (std::find(types.begin(), types.end(), *type) == types.end())
      fail(p.line, path + ": unknown type '" + *type + "' (expected one of: " + joinNames(types) + ")");
    ParsedValue parsed = parseValue(*type, *value);
    if (parsed.problem != ValueProblem::None) fail(p.line, path + ": " + parsed.message);
    // Where the value was declared, for validation's type check (declaredAt).
    parsed.entry.setDocString(file_ + ":" + std::to_string(p.line));
    out.setEntry(name, parsed.entry);
  }
};

}  // namespace

std::string readDeckText(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  requireInput(fs::exists(status), path + ": cannot open deck file (no such file)");
  requireInput(!fs::is_directory(status), path + ": is a directory, not a deck file");
  std::ifstream in(path, std::ios::binary);
  requireInput(in.is_open(), path + ": cannot open deck file (" + std::strerror(errno) + ")");
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    requireInput(text.size() <= kMaxDeckBytes, path + ": larger than " + std::to_string(kMaxDeckBytes >> 20) +
                                                    " MB, not a deck (a mesh or results file?)");
  }
  requireInput(!in.bad(), path + ": cannot read the deck file");
  return text;
}

Teuchos::RCP<Teuchos::ParameterList> parseDeck(const std::string& text, const std::string& file) {
  const XmlElement root = parseXml(text, file);
  if (root.tag != "ParameterList")
    throw InputError(file + ":" + std::to_string(root.line) + ": the root element must be <ParameterList>, not <" +
                     root.tag + ">");
  const std::string* name = root.attribute("name");
  auto deck = Teuchos::rcp(new Teuchos::ParameterList(name != nullptr && !name->empty() ? *name : "ANONYMOUS"));
  DeckBuilder(file).fill(root, "", *deck);
  return deck;
}

Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path) { return parseDeck(readDeckText(path), path); }

std::string declaredAt(const Teuchos::ParameterEntry& entry) { return entry.docString(); }

ParsedValue setTypedFromText(Teuchos::ParameterList& list, const std::string& name, const Teuchos::ParameterEntry& typed,
                             const std::string& text) {
  const std::string type = deckTypeOf(typed);
  if (type.empty()) {
    ParsedValue refused;
    refused.problem = ValueProblem::Malformed;
    refused.message = "a " + std::string(typed.getAny(false).typeName()) + " cannot be read from text";
    return refused;
  }
  ParsedValue parsed = parseValue(type, text, true);
  if (parsed.problem == ValueProblem::None) list.setEntry(name, parsed.entry);
  return parsed;
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
      const ParsedValue parsed = setTypedFromText(*list, name, typed, value);
      requireInput(parsed.problem == ValueProblem::None, "--set " + item + ": " + parsed.message);
    } else {
      list->set(name, value);
    }
    paths.insert(path);
  }
  return paths;
}

}  // namespace contessa::deck
