#include "mechanics/Quad4Enhanced.hpp"

#include "mechanics/Quad4.hpp"

namespace contessa::mechanics {

Quad4Enhanced::Quad4Enhanced() : EnhancedStrainElement(bilinearQuadrilateral()) {}

std::string Quad4Enhanced::name() const { return kName; }

}  // namespace contessa::mechanics
