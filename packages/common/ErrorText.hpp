#pragma once
// The text of an exception from a library, made fit for one line on a user's terminal. Teuchos
// (TEUCHOS_TEST_FOR_EXCEPTION) wraps its message in "FILE.cpp:LINE: Throw number = N Throw test that
// evaluated to true: EXPR", which says nothing a user can act on: only the message itself is kept.
#include <exception>
#include <regex>
#include <string>

namespace contessa {

/// `text` without Teuchos' throw location, throw number and test expression, on one line, at most
/// `maxLength` characters.
inline std::string plainMessage(std::string text, std::size_t maxLength = 300) {
  static const std::string kTest = "Throw test that evaluated to true:";
  for (auto test = text.find(kTest); test != std::string::npos; test = text.find(kTest)) {
    auto body = text.find("\n\n", test);  // the expression ends at the first blank line
    if (body == std::string::npos) body = text.find('\n', test);
    const auto before = text.rfind("Throw number", test);
    const auto start = before == std::string::npos ? test : before;
    text.erase(start, body == std::string::npos ? std::string::npos : body - start);
  }
  text = std::regex_replace(text, std::regex(R"(Throw number = \d+)"), " ");
  text = std::regex_replace(text, std::regex(R"([^\s:]+\.(cpp|hpp|h|cc|C):\d+:)"), " ");
  text = std::regex_replace(text, std::regex(R"(\s+)"), " ");
  const auto first = text.find_first_not_of(' ');
  text = first == std::string::npos ? std::string() : text.substr(first, text.find_last_not_of(' ') - first + 1);
  if (text.size() > maxLength) text = text.substr(0, maxLength) + "...";
  return text.empty() ? "unknown error" : text;
}

inline std::string plainMessage(const std::exception& e, std::size_t maxLength = 300) {
  return plainMessage(std::string(e.what()), maxLength);
}

}  // namespace contessa
