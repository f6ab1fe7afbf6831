// Element registry: one row per kernel. Adding an element = its reference-element (and enhanced-mode)
// traits, a make function like Quad4.cpp's or Hex8.cpp's, and its rows here.
#include "common/Registry.hpp"
#include "mechanics/Element.hpp"
#include "mechanics/Hex8.hpp"
#include "mechanics/Quad4.hpp"
#include "mechanics/QuadraticCells.hpp"
#include "mechanics/Simplices.hpp"
#include "mechanics/Wedges.hpp"

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
                  {"Hex8 Enhanced", "Hex8 with the 9 Simo–Armero enhanced modes: exact in pure bending", &makeHex8Enhanced},
                  {"Tri3", "3-node triangle (2D, plane strain), 1 point: constant strain, locks", &makeTri3},
                  {"Tri6", "6-node quadratic triangle (2D, plane strain), 3 points", &makeTri6},
                  {"Q8", "8-node serendipity quadrilateral (2D, plane strain), 3 × 3 Gauss", &makeQ8},
                  {"Q9", "9-node Lagrange quadrilateral (2D, plane strain), 3 × 3 Gauss", &makeQ9},
                  {"Tri3 Axisymmetric", "Tri3 revolved about the y axis, 3 points", &makeTri3Axisymmetric},
                  {"Tri6 Axisymmetric", "Tri6 revolved about the y axis", &makeTri6Axisymmetric},
                  {"Q8 Axisymmetric", "Q8 revolved about the y axis", &makeQ8Axisymmetric},
                  {"Q9 Axisymmetric", "Q9 revolved about the y axis", &makeQ9Axisymmetric},
                  {"Tet4", "4-node tetrahedron (3D), 1 point: constant strain, locks", &makeTet4},
                  {"Tet10", "10-node quadratic tetrahedron (3D), 4 points", &makeTet10},
                  {"Hex20", "20-node serendipity hexahedron (3D), 3 × 3 × 3 Gauss", &makeHex20},
                  {"Hex27", "27-node Lagrange hexahedron (3D), 3 × 3 × 3 Gauss", &makeHex27},
                  {"Wedge6", "6-node wedge (3D prism), 3 × 2 points: locks like Hex8", &makeWedge6},
                  {"Wedge15", "15-node quadratic wedge (3D prism), 3 × 3 points", &makeWedge15}});
  return rows;
}

}  // namespace

std::vector<std::string> ElementFactory::names() { return registry().names(); }

std::unique_ptr<ElementKernel> ElementFactory::create(const std::string& name, const std::string& where) {
  const auto& row = registry().lookup(name, where);
  return row.factory(row.name);
}

}  // namespace contessa::mechanics
