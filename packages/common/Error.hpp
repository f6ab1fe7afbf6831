#pragma once
// User-facing errors. An InputError names the deck parameter or file and what was expected; the
// application prints its one-line message and exits with status 2. Internal invariants use assert().
#include <stdexcept>
#include <string>

namespace contessa {

/// Bad input: a deck parameter, a mesh file, a name that does not exist. One line, always on.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/// Throws InputError(message) when the condition is false (like deal.II's AssertThrow).
inline void requireInput(bool condition, const std::string& message) {
  if (!condition) throw InputError(message);
}

}  // namespace contessa
