#include "mechanics/LinearElastic.hpp"

namespace contessa::mechanics {

Teuchos::RCP<const Teuchos::ParameterList> LinearElastic::validParameters() {
  return isotropicElasticParameters(
      kModelName, "Small-strain linear elasticity: sigma = lambda tr(eps) I + 2 mu eps, eps = sym(F - I)");
}

std::unique_ptr<Material> LinearElastic::create(const Teuchos::ParameterList& params, const std::string& where) {
  return std::make_unique<LinearElastic>(readLameConstants(params, where));
}

bool LinearElastic::firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const {
  // No admissibility check: a geometrically linear law has no notion of inversion.
  const double lambda = lame_.lambda, mu = lame_.mu;
  const Tensor2 I = identity2();
  Tensor2 eps{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) eps[idx2(i, j)] = 0.5 * (F[idx2(i, j)] + F[idx2(j, i)]) - I[idx2(i, j)];
  const double trEps = trace(eps);
  for (int n = 0; n < 9; ++n) P[n] = lambda * trEps * I[n] + 2.0 * mu * eps[n];
  if (A) {
    // ∂σ_ij/∂F_kl with ∂ε_ij/∂F_kl = ½ (δ_ik δ_jl + δ_il δ_jk): the (minor-symmetric) elasticity tensor.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            (*A)[idx4(i, j, k, l)] = lambda * I[idx2(i, j)] * I[idx2(k, l)] +
                                     mu * (I[idx2(i, k)] * I[idx2(j, l)] + I[idx2(i, l)] * I[idx2(j, k)]);
  }
  return true;
}

}  // namespace contessa::mechanics
