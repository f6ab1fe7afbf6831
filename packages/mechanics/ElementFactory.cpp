// Element registry: one row per kernel. Adding Hex8 = its reference-element (and enhanced-mode)
// traits, a make function like Quad4.cpp's, and its rows here.
#include <array>

#include "common/Error.hpp"
#include "mechanics/Element.hpp"
#include "mechanics/Quad4.hpp"

namespace contessa::mechanics {
namespace {

struct ElementEntry {
  const char* name;
  std::unique_ptr<ElementKernel> (*create)(const std::string& name);
};

const std::array<ElementEntry, 2> kRegistry = {ElementEntry{"Q4", &makeQuad4},
                                               ElementEntry{"Q4 Enhanced", &makeQuad4Enhanced}};

}  // namespace

std::vector<std::string> ElementFactory::names() {
  std::vector<std::string> result;
  for (const auto& e : kRegistry) result.emplace_back(e.name);
  return result;
}

std::unique_ptr<ElementKernel> ElementFactory::create(const std::string& name, const std::string& where) {
  for (const auto& e : kRegistry)
    if (name == e.name) return e.create(e.name);
  std::string known;
  for (const auto& e : kRegistry) known += (known.empty() ? "" : ", ") + std::string(e.name);
  throw InputError(where + ": unknown element '" + name + "' (known: " + known + ")");
}

}  // namespace contessa::mechanics
