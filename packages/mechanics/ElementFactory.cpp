// Element registry: one row per kernel. Adding an element = its reference-element (and enhanced-mode)
// traits, a make function like Quad4.cpp's or Hex8.cpp's, and its rows here.
#include "common/Registry.hpp"
#include "mechanics/Element.hpp"
#include "mechanics/Hex8.hpp"
#include "mechanics/Quad4.hpp"

namespace contessa::mechanics {
namespace {

using MakeElement = std::unique_ptr<ElementKernel> (*)(const std::string& name);

const Registry<RegistryRow<MakeElement>>& registry() {
  static const Registry<RegistryRow<MakeElement>> rows(
      "element", {{"Q4", "4-node quadrilateral (2D, plane strain), full 2 × 2 Gauss", &makeQuad4},
                  {"Q4 Enhanced", "Q4 with the 4 Simo–Armero enhanced modes: exact in pure bending", &makeQuad4Enhanced},
                  {"Q4 Axisymmetric", "Q4 revolved about the y axis (r = x, z = y), full circumference", &makeQuad4Axisymmetric},
                  {"Q4 Enhanced Axisymmetric", "Q4 Enhanced revolved about the y axis: in-plane modes, hoop strain u_r / R",
                   &makeQuad4EnhancedAxisymmetric},
                  {"Hex8", "8-node hexahedron (3D), full 2 × 2 × 2 Gauss", &makeHex8},
                  {"Hex8 Enhanced", "Hex8 with the 9 Simo–Armero enhanced modes: exact in pure bending", &makeHex8Enhanced}});
  return rows;
}

}  // namespace

std::vector<std::string> ElementFactory::names() { return registry().names(); }

std::unique_ptr<ElementKernel> ElementFactory::create(const std::string& name, const std::string& where) {
  const auto& row = registry().lookup(name, where);
  return row.factory(row.name);
}

}  // namespace contessa::mechanics
