#include "output/DeckText.hpp"

#include <charconv>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterEntryXMLConverterDB.hpp>

namespace contessa::output {

namespace {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  return out;
}

// The shortest decimal text that reads back as the same double.
std::string shortest(double value) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

std::string valueText(const Teuchos::ParameterEntry& entry) {
  if (entry.isType<double>()) return shortest(Teuchos::getValue<double>(entry));
  if (entry.isType<Teuchos::Array<double>>()) {
    std::string text = "{";
    for (double v : Teuchos::getValue<Teuchos::Array<double>>(entry)) text += (text.size() > 1 ? ", " : "") + shortest(v);
    return text + "}";
  }
  return Teuchos::ParameterEntryXMLConverterDB::getConverter(Teuchos::rcpFromRef(entry))->getValueAttributeValue(
      Teuchos::rcpFromRef(entry));
}

void append(const Teuchos::ParameterList& list, const std::string& name, const std::string& indent,
            std::vector<std::string>& lines) {
  lines.push_back(indent + "<ParameterList name=\"" + xmlEscaped(name) + "\">");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto& entry = list.entry(it);
    if (entry.isList()) {
      append(list.sublist(list.name(it)), list.name(it), indent + "  ", lines);
      continue;
    }
    const auto converter = Teuchos::ParameterEntryXMLConverterDB::getConverter(Teuchos::rcpFromRef(entry));
    lines.push_back(indent + "  <Parameter name=\"" + xmlEscaped(list.name(it)) + "\" type=\"" +
                    converter->getTypeAttributeValue() + "\" value=\"" + xmlEscaped(valueText(entry)) + "\"/>");
  }
  lines.push_back(indent + "</ParameterList>");
}

}  // namespace

std::vector<std::string> deckText(const Teuchos::ParameterList& deck) {
  std::vector<std::string> lines;
  // The reader does not keep the root's name (sublists carry their full path in theirs).
  append(deck, deck.name() == "ANONYMOUS" ? "Contessa" : deck.name(), "", lines);
  return lines;
}

}  // namespace contessa::output
