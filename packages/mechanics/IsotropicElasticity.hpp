#pragma once
// The two isotropic elastic constants shared by every law in this package: deck parameters
// ("Young's Modulus", "Poisson's Ratio"), their validation, and the Lamé constants.
#include <string>

#include <Teuchos_ParameterList.hpp>

namespace contessa::mechanics {

struct LameConstants {
  double lambda = 0.0;  ///< λ = E ν / ((1 + ν)(1 − 2ν))
  double mu = 0.0;      ///< μ = E / (2 (1 + ν)), the shear modulus
};

/// λ, μ from Young's modulus and Poisson's ratio (no checks; see readLameConstants).
LameConstants lameFromYoungPoisson(double youngsModulus, double poissonsRatio);

/// Valid parameters of an isotropic elastic law named `model`: "Model", "Young's Modulus"
/// (required, > 0) and "Poisson's Ratio" (in (−1, 0.5), default 0). `description` documents the law.
Teuchos::RCP<Teuchos::ParameterList> isotropicElasticParameters(const std::string& model,
                                                                const std::string& description);

/// Reads and checks E and ν from `params`; throws InputError naming `where + "/<parameter>"` when
/// one is missing, not a number, or outside its range.
LameConstants readLameConstants(const Teuchos::ParameterList& params, const std::string& where);

}  // namespace contessa::mechanics
