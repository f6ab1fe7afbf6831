#pragma once
// A small XML reader for decks. Teuchos' parser reports errors with its own throw text and no usable
// position for most mistakes, and keeps no line numbers in the tree; this one keeps the line of every
// element and says what is wrong where, in words a user can act on ("deck.xml:12: unclosed element
// <Parameter name="Value"> ..."). It reads the XML a deck needs: elements, attributes, character data,
// comments, the <?xml ...?> declaration, the five predefined entities and character references; UTF-8
// with or without a byte-order mark; any line endings.
#include <string>
#include <utility>
#include <vector>

namespace contessa::deck {

struct XmlElement {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attributes;  ///< in file order, entities decoded
  std::vector<XmlElement> children;
  std::string text;   ///< character data directly inside this element (entities decoded)
  int line = 0;       ///< line of the element's '<'
  int textLine = 0;   ///< line of the first non-blank character data (0: none)

  /// The attribute's value, or nullptr when the element has no such attribute.
  const std::string* attribute(const std::string& name) const;
  /// `<tag name="...">` (or `<tag>`), for messages.
  std::string describe() const;
};

/// Parses a whole document (`text` is the file's content) and returns its root element. Throws
/// InputError "FILE:LINE: what is wrong" (FILE is `file`) when the text is not well-formed XML with one
/// root element, is empty, or is not text at all.
XmlElement parseXml(const std::string& text, const std::string& file);

}  // namespace contessa::deck
