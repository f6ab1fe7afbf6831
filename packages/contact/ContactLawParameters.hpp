#pragma once
// Parameters of the penalty contact law with Coulomb friction (Section 3 of the reference paper).
#include "common/Error.hpp"

#include <string>

namespace contessa::contact {

struct ContactLawParameters {
  double normalPenalty = 0.0;        ///< ε_N, eq. (16)
  double tangentialPenalty = 0.0;    ///< ε_T, eq. (17), (20); unused when μ = 0
  double frictionCoefficient = 0.0;  ///< μ, eq. (18)–(19); 0 selects the frictionless path

  bool isFrictionless() const { return frictionCoefficient == 0.0; }

  /// Throws InputError naming the offending parameter.
  void validate() const {
    requireInput(normalPenalty > 0.0,
                 "contact: the normal penalty epsilon_N must be > 0, got " + std::to_string(normalPenalty));
    requireInput(frictionCoefficient >= 0.0,
                 "contact: the friction coefficient mu must be >= 0, got " + std::to_string(frictionCoefficient));
    requireInput(isFrictionless() || tangentialPenalty > 0.0,
                 "contact: the tangential penalty epsilon_T must be > 0 when mu > 0, got " +
                     std::to_string(tangentialPenalty));
  }
};

}  // namespace contessa::contact
