#pragma once
// Parameters of the penalty contact law with Coulomb friction (Section 3 of the reference paper).
#include "common/Error.hpp"

#include <string>

namespace contessa::contact {

/// ε_N, ε_T, μ of eq. (16)–(23) and the elastic-slip tolerance that ties the stick penalty to the
/// normal pressure (docs/theory-contact.md §5):
///
///   Slip tolerance s = 0:  ε_T = tangentialPenalty, the paper's constant stick penalty, eq. (17);
///   Slip tolerance s > 0:  ε_T = μ|t_N| / (s L_k), capped by tangentialPenalty when that is > 0,
///
/// where L_k is the mean length of the slave sides at the node. A node then sticks while its elastic slip
/// is below s L_k, whatever its pressure, instead of below μ|t_N|/ε_T, which vanishes with the pressure.
/// The deck's default is s = 0.005 (ProblemDefinition); this struct's default 0 is the paper's law.
struct ContactLawParameters {
  /// How the Kuhn–Tucker and stick conditions are enforced (docs/theory-contact.md §15): by the penalty
  /// regularisation alone (eq. 16–17), or by an augmented Lagrangian whose multipliers are updated
  /// (Uzawa) at the end of each increment until the penetration and the elastic slip are below their
  /// tolerances.
  enum class Enforcement { Penalty, AugmentedLagrangian };

  double normalPenalty = 0.0;        ///< ε_N, eq. (16)
  double tangentialPenalty = 0.0;    ///< ε_T of eq. (17) (s = 0), or its upper bound (s > 0; 0 = none)
  double frictionCoefficient = 0.0;  ///< μ, eq. (18)–(19); 0 selects the frictionless path
  double slipTolerance = 0.0;        ///< s: allowable elastic slip over the slave facet length; 0 = constant ε_T
  // The augmented Lagrangian (last, so that brace initialisations of the penalty law read as before).
  Enforcement enforcement = Enforcement::Penalty;
  /// Augmented Lagrangian: the largest penetration −g_N allowed, as a fraction of L_k (slave facet length).
  double penetrationTolerance = 0.0;
  /// Augmented Lagrangian: the largest elastic slip of a sticking node within an increment, as a fraction
  /// of L_k.
  double elasticSlipTolerance = 0.0;
  /// Augmented Lagrangian: the most multiplier updates per increment.
  int maxAugmentations = 0;

  bool isFrictionless() const { return frictionCoefficient == 0.0; }
  bool hasSlipTolerance() const { return slipTolerance > 0.0; }
  bool isAugmented() const { return enforcement == Enforcement::AugmentedLagrangian; }

  /// The most the augmented Lagrangian grows an interface's normal penalty over the deck's
  /// (model::grownPenalty; docs/theory-contact.md eq. 15.5). With friction it grows only where an update has
  /// measured a slow Uzawa rate (model::ContactAssembly::augment), which the run cannot promise at its start.
  static constexpr double kMaxPenaltyGrowth = 30.0;
  /// ε_N as far as the run may take it for certain: the deck's, times kMaxPenaltyGrowth where the augmented
  /// Lagrangian grows it at its first update (frictionless); with friction the deck's.
  double largestNormalPenalty() const {
    return isAugmented() && isFrictionless() ? kMaxPenaltyGrowth * normalPenalty : normalPenalty;
  }

  /// Throws InputError naming the offending parameter.
  void validate() const {
    requireInput(normalPenalty > 0.0,
                 "contact: the normal penalty epsilon_N must be > 0, got " + std::to_string(normalPenalty));
    requireInput(frictionCoefficient >= 0.0,
                 "contact: the friction coefficient mu must be >= 0, got " + std::to_string(frictionCoefficient));
    requireInput(tangentialPenalty >= 0.0,
                 "contact: the tangential penalty epsilon_T must be >= 0, got " + std::to_string(tangentialPenalty));
    requireInput(slipTolerance >= 0.0,
                 "contact: the slip tolerance must be >= 0, got " + std::to_string(slipTolerance));
    requireInput(penetrationTolerance >= 0.0 && elasticSlipTolerance >= 0.0 && maxAugmentations >= 0,
                 "contact: the augmented Lagrangian's tolerances and Max Augmentations must be >= 0");
    requireInput(isFrictionless() || hasSlipTolerance() || tangentialPenalty > 0.0,
                 "contact: the tangential penalty epsilon_T must be > 0 when mu > 0 and the slip tolerance is 0, got " +
                     std::to_string(tangentialPenalty));
  }
};

}  // namespace contessa::contact
