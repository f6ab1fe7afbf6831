#pragma once
// "Q4 Enhanced": bilinear quadrilateral with 4 enhanced-strain modes (Simo & Armero 1992), 2 × 2
// Gauss, condensed at the element. Exact for pure bending of rectangles and free of volumetric
// locking in the small-strain limit; the 4 α per element are its internal variables.
#include <string>

#include "mechanics/EnhancedStrainElement.hpp"

namespace contessa::mechanics {

class Quad4Enhanced final : public EnhancedStrainElement {
 public:
  static constexpr const char* kName = "Q4 Enhanced";
  Quad4Enhanced();
  std::string name() const override;
};

}  // namespace contessa::mechanics
