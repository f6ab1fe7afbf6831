#include "mechanics/LinearElastic.hpp"

namespace contessa::mechanics {

Teuchos::RCP<const Teuchos::ParameterList> LinearElastic::validParameters() {
  return isotropicElasticParameters(
      kModelName, "Small-strain linear elasticity: sigma = lambda tr(eps) I + 2 mu eps, eps = sym(F - I)");
}

std::unique_ptr<Material> LinearElastic::create(const Teuchos::ParameterList& params, const std::string& where) {
  return std::make_unique<LinearElastic>(readLameConstants(params, where));
}

template <int D>
bool LinearElastic::stress(const Matrix<D>& F, Matrix<D>& P, Tangent<D>* A) const {
  // No admissibility check: a geometrically linear law has no notion of inversion. Plane strain:
  // ε_33 = 0, so tr ε and the in-plane σ are those of the in-plane block.
  const double lambda = lame_.lambda, mu = lame_.mu;
  const auto delta = [](int i, int j) { return i == j ? 1.0 : 0.0; };
  Matrix<D> eps{};
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) eps[D * i + j] = 0.5 * (F[D * i + j] + F[D * j + i]) - delta(i, j);
  double trEps = 0.0;
  for (int i = 0; i < D; ++i) trEps += eps[D * i + i];
  for (int n = 0; n < D * D; ++n) P[n] = lambda * trEps * delta(n / D, n % D) + 2.0 * mu * eps[n];
  if (A) {
    // ∂σ_ij/∂F_kl with ∂ε_ij/∂F_kl = ½ (δ_ik δ_jl + δ_il δ_jk): the (minor-symmetric) elasticity tensor.
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        for (int k = 0; k < D; ++k)
          for (int l = 0; l < D; ++l)
            (*A)[((D * i + j) * D + k) * D + l] =
                lambda * delta(i, j) * delta(k, l) + mu * (delta(i, k) * delta(j, l) + delta(i, l) * delta(j, k));
  }
  return true;
}

template bool LinearElastic::stress<2>(const Matrix<2>&, Matrix<2>&, Tangent<2>*) const;
template bool LinearElastic::stress<3>(const Matrix<3>&, Matrix<3>&, Tangent<3>*) const;
template class MaterialLaw<LinearElastic>;

}  // namespace contessa::mechanics
