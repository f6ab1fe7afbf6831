// Element registry: one row per kernel. Adding Hex8 = one class + one row here.
#include <array>

#include "common/Error.hpp"
#include "mechanics/Element.hpp"
#include "mechanics/Quad4.hpp"
#include "mechanics/Quad4Enhanced.hpp"

namespace contessa::mechanics {
namespace {

struct ElementEntry {
  const char* name;
  std::unique_ptr<ElementKernel> (*create)();
};

template <class Kernel>
std::unique_ptr<ElementKernel> make() {
  return std::make_unique<Kernel>();
}

template <class Kernel>
constexpr ElementEntry entry() {
  return {Kernel::kName, &make<Kernel>};
}

constexpr std::array<ElementEntry, 2> kRegistry = {entry<Quad4>(), entry<Quad4Enhanced>()};

}  // namespace

std::vector<std::string> ElementFactory::names() {
  std::vector<std::string> result;
  for (const auto& e : kRegistry) result.emplace_back(e.name);
  return result;
}

std::unique_ptr<ElementKernel> ElementFactory::create(const std::string& name, const std::string& where) {
  for (const auto& e : kRegistry)
    if (name == e.name) return e.create();
  std::string known;
  for (const auto& e : kRegistry) known += (known.empty() ? "" : ", ") + std::string(e.name);
  throw InputError(where + ": unknown element '" + name + "' (known: " + known + ")");
}

}  // namespace contessa::mechanics
