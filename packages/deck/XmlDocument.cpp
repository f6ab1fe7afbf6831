#include "deck/XmlDocument.hpp"

#include <cstring>

#include "common/Error.hpp"

namespace contessa::deck {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n'; }
// XML names; bytes of multi-byte UTF-8 characters count as name characters.
bool isNameStart(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u >= 'A' && u <= 'Z') || (u >= 'a' && u <= 'z') || u == '_' || u == ':' || u >= 0x80;
}
bool isNameChar(char c) {
  return isNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

// The first characters of `text` on one line, for messages.
std::string snippet(const std::string& text, std::size_t pos) {
  std::string s = text.substr(pos, 40);
  s = s.substr(0, s.find('\n'));
  return s.size() < text.size() - pos && s.size() == 40 ? s + "..." : s;
}

std::string utf8(unsigned long code) {
  std::string out;
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
  return out;
}

class Parser {
 public:
  Parser(std::string text, std::string file) : s_(std::move(text)), file_(std::move(file)) {}

  XmlElement document() {
    skipMisc();
    if (atEnd()) fail(0, "the deck is empty (expected a <ParameterList> element)");
    if (peek() != '<' || !isNameStart(peek(1)))
      fail(line_, "not an XML deck: it must start with <ParameterList>, found '" + snippet(s_, pos_) + "'");
    XmlElement root = element();
    const int rootEnd = line_;
    skipMisc();
    if (atEnd()) return root;
    if (startsWith("</"))
      fail(line_, "'" + snippet(s_, pos_) + "' closes nothing: the root element " + root.describe() + " from line " +
                      std::to_string(root.line) + " already ended at line " + std::to_string(rootEnd) +
                      " (an extra </" + root.tag + ">?" + misalignmentHint() + ")");
    if (peek() == '<')
      fail(line_, "a second top-level element '" + snippet(s_, pos_) + "': the root element " + root.describe() +
                      " from line " + std::to_string(root.line) + " already ended at line " + std::to_string(rootEnd) +
                      " (an extra </" + root.tag + ">?" + misalignmentHint() + ")");
    fail(line_, "text after the end of the root element (line " + std::to_string(rootEnd) + "): '" +
                    snippet(s_, pos_) + "'");
  }

 private:
  std::string s_, file_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::size_t lineStart_ = 0;  // position of the current line's first character
  // The first end tag indented unlike its start tag: where a missing or extra end tag most likely is.
  std::string misaligned_;

  std::string misalignmentHint() const {
    return misaligned_.empty() ? std::string() : "; " + misaligned_;
  }

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(file_ + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what);
  }
  bool atEnd() const { return pos_ >= s_.size(); }
  char peek(std::size_t ahead = 0) const { return pos_ + ahead < s_.size() ? s_[pos_ + ahead] : '\0'; }
  bool startsWith(const char* literal) const { return s_.compare(pos_, std::strlen(literal), literal) == 0; }
  void advance(std::size_t n = 1) {
    for (; n > 0 && pos_ < s_.size(); --n, ++pos_)
      if (s_[pos_] == '\n') {
        ++line_;
        lineStart_ = pos_ + 1;
      }
  }
  bool skipSpace() {
    const std::size_t start = pos_;
    while (!atEnd() && isSpace(peek())) advance();
    return pos_ > start;
  }

  std::string name() {
    std::string n;
    while (!atEnd() && isNameChar(peek())) {
      n += peek();
      advance();
    }
    return n;
  }

  // Comments, declarations and processing instructions between elements.
  bool skipSpecial() {
    const int start = line_;
    if (startsWith("<!--")) {
      const auto end = s_.find("-->", pos_ + 4);
      if (end == std::string::npos) fail(start, "comment '<!--' is not closed (no '-->' before the end of the file)");
      advance(end + 3 - pos_);
      return true;
    }
    if (startsWith("<?")) {
      const auto end = s_.find("?>", pos_ + 2);
      if (end == std::string::npos) fail(start, "'<?' is not closed (no '?>' before the end of the file)");
      advance(end + 2 - pos_);
      return true;
    }
    if (startsWith("<![CDATA[")) fail(start, "CDATA sections are not supported in a deck");
    if (startsWith("<!")) fail(start, "'" + snippet(s_, pos_) + "': DOCTYPE and other declarations are not supported in a deck");
    return false;
  }
  void skipMisc() {
    while (skipSpace() || skipSpecial()) {}
  }

  // After '&': a predefined entity or a character reference.
  std::string reference() {
    const int at = line_;
    const auto semicolon = s_.find(';', pos_);
    const std::string ref = semicolon == std::string::npos || semicolon - pos_ > 12 ? "" : s_.substr(pos_ + 1, semicolon - pos_ - 1);
    if (ref.empty() || ref.find_first_not_of("#0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz") != std::string::npos)
      fail(at, "a bare '&' (write & as &amp;)");
    advance(ref.size() + 2);
    if (ref == "amp") return "&";
    if (ref == "lt") return "<";
    if (ref == "gt") return ">";
    if (ref == "quot") return "\"";
    if (ref == "apos") return "'";
    if (ref[0] == '#' && ref.size() > 1) {
      const bool hex = ref[1] == 'x';
      const std::string digits = ref.substr(hex ? 2 : 1);
      char* end = nullptr;
      const unsigned long code = std::strtoul(digits.c_str(), &end, hex ? 16 : 10);
      if (!digits.empty() && *end == '\0' && code > 0 && code <= 0x10FFFF) return utf8(code);
    }
    fail(at, "unknown entity '&" + ref + ";' (known: &amp; &lt; &gt; &quot; &apos; and &#N;)");
  }

  std::string attributeValue(const XmlElement& e, const std::string& attribute) {
    const int start = line_;
    const std::string what = e.describe() + ": the value of '" + attribute + "'";
    const char quote = peek();
    if (quote != '"' && quote != '\'') {
      // U+201C/U+201D/U+2018/U+2019 (“ ” ‘ ’) and U+00AB/U+00BB (« »), as word processors write them.
      if (startsWith("\xE2\x80\x9C") || startsWith("\xE2\x80\x9D") || startsWith("\xE2\x80\x98") ||
          startsWith("\xE2\x80\x99") || startsWith("\xC2\xAB") || startsWith("\xC2\xBB"))
        fail(start, what + " is in typographic quotes (" + attribute + "=" + snippet(s_, pos_) +
                        "); use straight quotes: " + attribute + "=\"...\"");
      fail(start, what + " must be in quotes: " + attribute + "=\"...\"");
    }
    advance();
    std::string value;
    while (true) {
      if (atEnd()) fail(start, what + " is not closed: the file ends first (a truncated file, or a missing " + quote + "?)");
      const char c = peek();
      if (c == quote) break;
      if (c == '<') fail(line_, "'<' in " + what + " (a missing closing quote? write < as &lt;)");
      if (c == '&') {
        value += reference();
      } else {
        value += c;
        advance();
      }
    }
    advance();
    return value;
  }

  XmlElement element() {
    XmlElement e;
    e.line = line_;
    const std::size_t column = pos_ - lineStart_;
    advance();  // '<'
    e.tag = name();
    bool empty = false;
    while (true) {
      const bool hadSpace = skipSpace();
      if (atEnd())
        fail(e.line, "the file ends inside the tag " + e.describe() + " that starts here (a truncated file?)");
      const char c = peek();
      if (c == '>') {
        advance();
        break;
      }
      if (c == '/') {
        advance();
        if (peek() != '>') fail(line_, "expected '>' after '/' in " + e.describe());
        advance();
        empty = true;
        break;
      }
      if (!isNameStart(c) || !hadSpace)
        fail(line_, "unexpected '" + snippet(s_, pos_).substr(0, 1) + "' in the tag " + e.describe() +
                        " (expected name=\"value\", '>' or '/>')");
      const std::string attribute = name();
      skipSpace();
      if (peek() != '=') fail(line_, "attribute '" + attribute + "' in " + e.describe() + " has no value (expected " + attribute + "=\"...\")");
      advance();
      skipSpace();
      if (e.attribute(attribute) != nullptr) fail(line_, "attribute '" + attribute + "' given twice in " + e.describe());
      std::string value = attributeValue(e, attribute);
      e.attributes.emplace_back(attribute, std::move(value));
    }
    if (!empty) content(e, column);
    return e;
  }

  void content(XmlElement& e, std::size_t column) {
    while (true) {
      if (atEnd())
        fail(e.line, "unclosed element " + e.describe() + " (the file ends at line " + std::to_string(line_) +
                         " before its </" + e.tag + ">" + misalignmentHint() + ")");
      if (startsWith("</")) {
        const int at = line_;
        const std::size_t closeColumn = pos_ - lineStart_;
        advance(2);
        const std::string closing = name();
        skipSpace();
        if (peek() != '>') fail(at, "malformed end tag '</" + closing + snippet(s_, pos_) + "' (expected </" + closing + ">)");
        advance();
        if (closing != e.tag)
          fail(e.line, "unclosed element " + e.describe() + " (line " + std::to_string(at) + " has </" + closing + "> first" +
                           (e.tag == "Parameter" ? "; a Parameter ends with '/>')" : ")"));
        if (misaligned_.empty() && at != e.line && closeColumn != column)
          misaligned_ = "line " + std::to_string(at) + " closes " + e.describe() + " (line " + std::to_string(e.line) +
                        ") at another indentation";
        return;
      }
      if (skipSpecial()) continue;
      if (peek() == '<') {
        if (!isNameStart(peek(1))) fail(line_, "'<' that starts no element in " + e.describe() + " (write < as &lt;)");
        e.children.push_back(element());
        continue;
      }
      if (peek() == '&') {
        if (e.textLine == 0) e.textLine = line_;
        e.text += reference();
        continue;
      }
      if (e.textLine == 0 && !isSpace(peek())) e.textLine = line_;
      e.text += peek();
      advance();
    }
  }
};

}  // namespace

const std::string* XmlElement::attribute(const std::string& name) const {
  for (const auto& [key, value] : attributes)
    if (key == name) return &value;
  return nullptr;
}

std::string XmlElement::describe() const {
  const std::string* n = attribute("name");
  return "<" + tag + (n != nullptr ? " name=\"" + *n + "\"" : std::string()) + ">";
}

XmlElement parseXml(const std::string& text, const std::string& file) {
  std::size_t start = 0;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;  // UTF-8 byte-order mark
  if (text.compare(0, 2, "\xFF\xFE") == 0 || text.compare(0, 2, "\xFE\xFF") == 0)
    throw InputError(file + ": the deck is UTF-16 text; save it as UTF-8");
  if (text.find('\0') != std::string::npos)
    throw InputError(file + ": not an XML deck (it holds binary data; a mesh or results file?)");
  // XML end-of-line handling: CR LF and lone CR read as LF.
  std::string normalized;
  normalized.reserve(text.size());
  for (std::size_t i = start; i < text.size(); ++i) {
    if (text[i] == '\r') {
      normalized += '\n';
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
    } else {
      normalized += text[i];
    }
  }
  return Parser(std::move(normalized), file).document();
}

}  // namespace contessa::deck
