#pragma once
// What the 2D and 3D mortar interface tests share: one evaluation of an interface into dense arrays, and
// the central-difference checks of its tangent and of its load derivative ∂r/∂λ (the project's rule: every
// tangent against a finite-difference derivative of its residual).
#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/ContactInterface.hpp"

namespace contessa::contact::testing {

struct Assembled {
  std::vector<double> residual, tangent, dLambda;  // over every DOF of the test's nodes
  std::vector<SlaveNodeState> states;
  ContactCounts counts;
};

// Makes spec's master the rigid plate z = −0.03 over [−0.2, xMax] × [−0.1, yMax], its normal down (towards
// the slave faces at z = 0), moving by (0.1, −0.05, −0.02) per unit load factor: the 3D mortar tests'
// rigid master.
inline void setMovingRigidPlate(ContactInterfaceSpec& spec, double xMax, double yMax) {
  spec.rigidMaster = true;
  const double z = -0.03;
  spec.rigidSurface.points = {-0.2, -0.1, z, xMax, -0.1, z, xMax, yMax, z, -0.2, yMax, z};
  spec.rigidSurface.facets = {0, 3, 2, 1};  // clockwise from +z: normal down, towards the slave
  spec.rigidSurface.motion = {0.1, -0.05, -0.02};
}

// Evaluates `interface` at the coordinates x (Dim per node, node-major) and load factor λ without a
// commit: the residual and tangent of a Newton iterate.
template <int Dim>
Assembled evaluateOnly(ContactInterfaceBase& interface, const std::vector<double>& x, double lambda) {
  const int n = static_cast<int>(x.size());
  Assembled out{std::vector<double>(n, 0.0), std::vector<double>(n * n, 0.0), std::vector<double>(n, 0.0), {}, {}};
  interface.evaluate([&](GlobalIndex node, double* p) { std::copy(&x[Dim * node], &x[Dim * node] + Dim, p); }, lambda,
                     true, [&](const GlobalIndex* dofs, int m, const double* r, const double* k, const double* drdl) {
                       for (int a = 0; a < m; ++a) {
                         if (dofs[a] < 0) continue;
                         out.residual[dofs[a]] += r[a];
                         out.dLambda[dofs[a]] += drdl[a];
                         for (int b = 0; b < m; ++b)
                           if (dofs[b] >= 0) out.tangent[dofs[a] * n + dofs[b]] += k[a * m + b];
                       }
                     });
  return out;
}

// The residual of a trial evaluation at x and λ from `committed`'s state, on a copy (clone): a central
// difference's residuals all start from one committed state, and the commits leading there cost as much as
// the trial itself, so the tests make them once and evaluate copies.
template <int Dim>
std::vector<double> trialResidual(const ContactInterfaceBase& committed, const std::vector<double>& x, double lambda) {
  return evaluateOnly<Dim>(*committed.clone(), x, lambda).residual;
}

// Evaluates and commits `interface` at x and λ (evaluateOnly, then the committed states and counts).
template <int Dim>
Assembled assemble(ContactInterfaceBase& interface, const std::vector<double>& x, double lambda) {
  Assembled out = evaluateOnly<Dim>(interface, x, lambda);
  interface.commit();
  out.states = interface.committedStates();
  out.counts = interface.committedCounts();
  return out;
}

// The largest |(r(x + h e_j) − r(x − h e_j)) / 2h − K_ij| over the columns j of the dense tangent K
// (h = 1e-7), with the largest |K_ij| there in *scale; residualAt(y) is the residual at coordinates y.
template <class ResidualAt>
double tangentColumnsCentralDifferenceError(const std::vector<double>& tangent, const std::vector<double>& x,
                                            ResidualAt residualAt, const std::vector<int>& columns, double* scale) {
  const int n = static_cast<int>(x.size());
  const double h = 1e-7;
  double error = 0;
  *scale = 0;
  for (int j : columns) {
    auto plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    const auto rp = residualAt(plus), rm = residualAt(minus);
    for (int i = 0; i < n; ++i) {
      *scale = std::max(*scale, std::abs(tangent[i * n + j]));
      error = std::max(error, std::abs((rp[i] - rm[i]) / (2 * h) - tangent[i * n + j]));
    }
  }
  return error;
}

// The same over every column of K.
template <class ResidualAt>
double tangentCentralDifferenceError(const std::vector<double>& tangent, const std::vector<double>& x,
                                     ResidualAt residualAt, double* scale) {
  std::vector<int> every(x.size());
  for (std::size_t j = 0; j < every.size(); ++j) every[j] = static_cast<int>(j);
  return tangentColumnsCentralDifferenceError(tangent, x, residualAt, every, scale);
}

// The dof columns of `nodes`, Dim components each (node-major coordinates).
template <int Dim>
std::vector<int> nodeColumns(const std::vector<int>& nodes) {
  std::vector<int> columns;
  for (int node : nodes)
    for (int c = 0; c < Dim; ++c) columns.push_back(Dim * node + c);
  return columns;
}

// The same for ∂r/∂λ at λ; residualAt(μ) is the residual at load factor μ.
template <class ResidualAt>
double loadDerivativeCentralDifferenceError(const std::vector<double>& dLambda, double lambda, ResidualAt residualAt,
                                            double* scale) {
  const double h = 1e-7;
  const auto rp = residualAt(lambda + h), rm = residualAt(lambda - h);
  double error = 0;
  *scale = 0;
  for (std::size_t i = 0; i < dLambda.size(); ++i) {
    *scale = std::max(*scale, std::abs(dLambda[i]));
    error = std::max(error, std::abs((rp[i] - rm[i]) / (2 * h) - dLambda[i]));
  }
  return error;
}

// The 3 × 3-node slave face on z = 0 (nodes 0–8, unit facets) under two master quadrilaterals (nodes 9–14
// at y = −0.2 and 2.2, x = −0.1, 0.7, 2.1) at z = −penetration: the coordinates of MortarFacetPairTest's
// and MortarFriction3DTest's face.
inline std::vector<double> faceCoordinates(double penetration) {
  std::vector<double> x;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) x.insert(x.end(), {double(i), double(j), 0.0});
  for (double y : {-0.2, 2.2})
    for (double xm : {-0.1, 0.7, 2.1}) x.insert(x.end(), {xm, y, -penetration});
  return x;
}

// That face with every node moved a little: warped facets, clip edges inside the slave facets.
inline std::vector<double> unevenFace() {
  std::vector<double> x = faceCoordinates(0.02);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.013 * std::sin(1.7 * double(i) + 0.4);
  return x;
}

}  // namespace contessa::contact::testing
