#pragma once
#include <string>

namespace contessa::app {

/// The deck reference in Markdown, generated from the valid-parameter lists every configurable
/// class publishes (docs/deck-reference.md is this output; a test keeps it current).
std::string deckReference();

}  // namespace contessa::app
