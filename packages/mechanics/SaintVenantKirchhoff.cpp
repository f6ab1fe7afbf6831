#include "mechanics/SaintVenantKirchhoff.hpp"

namespace contessa::mechanics {

Teuchos::RCP<const Teuchos::ParameterList> SaintVenantKirchhoff::validParameters() {
  return isotropicElasticParameters(
      kModelName, "Saint Venant-Kirchhoff: S = lambda tr(E) I + 2 mu E, E = (C - I)/2 (large rotations, small strains)");
}

std::unique_ptr<Material> SaintVenantKirchhoff::create(const Teuchos::ParameterList& params,
                                                       const std::string& where) {
  return std::make_unique<SaintVenantKirchhoff>(readLameConstants(params, where));
}

template <int D>
bool SaintVenantKirchhoff::stress(const Matrix<D>& F, Matrix<D>& P, Tangent<D>* A) const {
  // The energy stays finite through inversion, but an inverted F is not a deformation: reject it
  // like every finite-strain law so the solver cuts back instead of converging to it.
  if (!(determinantOf<D>(F) > 0.0)) return false;
  const double lambda = lame_.lambda, mu = lame_.mu;
  // E = ½ (FᵀF − I), S = λ tr(E) I + 2μ E, P = F S. In plane strain E_33 = 0, so tr E and the
  // in-plane S, P are those of the in-plane block.
  Matrix<D> E{}, S{};
  for (int I = 0; I < D; ++I)
    for (int J = 0; J < D; ++J) {
      double C = 0.0;
      for (int k = 0; k < D; ++k) C += F[D * k + I] * F[D * k + J];
      E[D * I + J] = 0.5 * (C - (I == J ? 1.0 : 0.0));
    }
  double trE = 0.0;
  for (int I = 0; I < D; ++I) trE += E[D * I + I];
  for (int n = 0; n < D * D; ++n) S[n] = 2.0 * mu * E[n];
  for (int I = 0; I < D; ++I) S[D * I + I] += lambda * trE;
  for (int i = 0; i < D; ++i)
    for (int J = 0; J < D; ++J) {
      double s = 0.0;
      for (int K = 0; K < D; ++K) s += F[D * i + K] * S[D * K + J];
      P[D * i + J] = s;
    }
  if (A) {
    // A_iJkL = δ_ik S_JL + F_iM ℂ_MJNL F_kN, ℂ_MJNL = λ δ_MJ δ_NL + μ (δ_MN δ_JL + δ_ML δ_JN),
    // i.e. the geometric term plus λ F_iJ F_kL + μ ((F Fᵀ)_ik δ_JL + F_iL F_kJ). The two products of
    // F are written for every entry (runs of D over L, which vectorise), the two Kronecker terms added
    // to the D³ entries they touch only: about 3 operations per entry instead of a branch-laden 10.
    Matrix<D> lambdaF, muF;
    for (int n = 0; n < D * D; ++n) {
      lambdaF[n] = lambda * F[n];
      muF[n] = mu * F[n];
    }
    Tangent<D>& a = *A;
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        for (int k = 0; k < D; ++k)
          for (int L = 0; L < D; ++L)
            a[((D * i + J) * D + k) * D + L] = lambdaF[D * i + J] * F[D * k + L] + muF[D * i + L] * F[D * k + J];
    for (int i = 0; i < D; ++i)
      for (int k = 0; k < D; ++k) {
        double muB = 0.0;  // μ (F Fᵀ)_ik
        for (int M = 0; M < D; ++M) muB += muF[D * i + M] * F[D * k + M];
        for (int J = 0; J < D; ++J) a[((D * i + J) * D + k) * D + J] += muB;
      }
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        for (int L = 0; L < D; ++L) a[((D * i + J) * D + i) * D + L] += S[D * J + L];
  }
  return true;
}

template bool SaintVenantKirchhoff::stress<2>(const Matrix<2>&, Matrix<2>&, Tangent<2>*) const;
template bool SaintVenantKirchhoff::stress<3>(const Matrix<3>&, Matrix<3>&, Tangent<3>*) const;
template class MaterialLaw<SaintVenantKirchhoff>;

}  // namespace contessa::mechanics
