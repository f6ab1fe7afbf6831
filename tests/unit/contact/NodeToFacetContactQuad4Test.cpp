// The node-to-face contact element on a 4-node master face (3D, 15 dofs): consistent tangent against
// central differences of the residual in normal contact, stick and slip (with and without the slip
// tolerance), at a face centre, near an edge, on a warped face and with large sliding; frame invariance;
// the slip direction; Newton's quadratic convergence on a one-node problem.
#include "ElementTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using Facet = cc::Quad4Facet;
using Element = cc::NodeToFacetContact<Facet>;
using Geometry = cc::NodeToFacetGeometry<Facet>;
using Face = std::array<Vector<3>, 4>;
constexpr int kN = 15;
using Mat = cc::Matrix<kN, kN>;
using Vec = Vector<kN>;

namespace {

// Counter-clockwise seen from +z: n̄ = ā_1 × ā_2 points to +z (out of a master body below).
const Face kFlat{{{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {2.0, 2.0, 0.0}, {0.0, 2.0, 0.0}}};
const Face kSkewed{{{0.0, 0.0, 0.0}, {2.4, 0.2, 0.0}, {2.1, 1.8, 0.0}, {-0.3, 2.2, 0.0}}};  // flat, not a parallelogram
const Face kWarped{{{0.0, 0.0, 0.0}, {2.0, 0.1, 0.4}, {2.2, 2.0, -0.1}, {-0.1, 1.9, 0.3}}};  // b̄_12 ≠ 0

/// Slave node at surface point ξ of `face`, at signed distance `gap` along n̄(ξ): it projects on ξ.
Geometry slaveAt(const Face& face, Vector<2> xi, double gap) {
  const auto p = cc::FaceProjection3D::evaluateAt({0.0, 0.0, 0.0}, face, xi);
  return {cc::add(p.position, cc::scaled(gap, p.normal)), face};
}

cc::ContactHistory<2> inContact(int facet, Vector<2> xiN, Vector<2> tractionN, ContactStatus status, double slip = 0.0) {
  return ct::committedHistory<2>(facet, xiN, tractionN, status, slip);
}

struct Configuration {
  std::string name;
  Face face;
  Vector<2> xi;   // current ξ̄
  Vector<2> xiN;  // committed ξ_n
  double gap;     // current g_N (< 0: penetrating)
};

// The penetration is a few percent of the face size, so the geometric terms (∝ g_N/l, t_T/t_N) and the
// curvature terms (∝ g_N b̄_12) are visible well above the FD error.
const Configuration kConfigurations[] = {
    {"centre", kFlat, {0.05, -0.03}, {-0.02, 0.04}, -0.04},
    {"near_edge", kSkewed, {0.96, 0.2}, {0.90, 0.26}, -0.03},
    {"warped", kWarped, {-0.3, 0.4}, {-0.38, 0.31}, -0.06},
    {"warped_corner", kWarped, {0.93, -0.95}, {0.85, -0.9}, -0.05},
    {"large_sliding", kWarped, {0.7, -0.5}, {-0.8, 0.6}, -0.05},
    // History carried over two faces (transferHistory): ξ_n lies far outside this face.
    {"from_previous_faces", kWarped, {-0.6, 0.2}, {-3.1, 0.45}, -0.04},
};


struct Case {
  const char* law;
  cc::ContactLawParameters parameters;
  Vector<2> committedTraction;
  ContactStatus expected;
};

// ε_N = 1e3, ε_T = 5e2. Stick: μ large enough for every configuration; slip: μ = 0.2.
const Case kCases[] = {
    {"normal_only", {1e3, 0.0, 0.0}, {0.0, 0.0}, ContactStatus::Slip},
    {"stick", {1e3, 5e2, 100.0}, {1.5, -0.8}, ContactStatus::Stick},
    {"slip", {1e3, 5e2, 0.2}, {1.5, -0.8}, ContactStatus::Slip},
};

}  // namespace

TEST(NodeToFacetContactQuad4, ConsistentTangentMatchesCentralDifferences) {
  ct::TangentCheck check{ct::kFdTolerance};
  for (const Case& c : kCases) {
    const Element element(c.parameters);
    for (const Configuration& conf : kConfigurations) {
      SCOPED_TRACE(std::string(c.law) + " / " + conf.name);
      const auto g = slaveAt(conf.face, conf.xi, conf.gap);
      const auto committed = inContact(7, conf.xiN, c.committedTraction, ContactStatus::Stick);
      const auto r = element.evaluate(g, 7, committed);
      ASSERT_EQ(r.status, c.expected);
      EXPECT_NEAR(r.projection.xi[0], conf.xi[0], 1e-12);
      EXPECT_NEAR(r.projection.xi[1], conf.xi[1], 1e-12);
      EXPECT_NEAR(r.projection.gap, conf.gap, 1e-12);
      check.expectClose(r.tangent, ct::finiteDifferenceTangent(element, g, 7, committed, ct::kFdStep),
                        std::string(c.law) + " " + conf.name);
    }
  }
  check.printWorst("Quad4");
}

// ε_T = μ|t_N|/(s L) with its ∂t_T/∂t_N term, in stick and slip, capped or not (ct::kSlipToleranceCases),
// at a normal penetration and at 2.5e-4 of it (a nearly unloaded node).
TEST(NodeToFacetContactQuad4, SlipToleranceTangentMatchesCentralDifferences) {
  ct::checkSlipToleranceTangents<Facet>(
      kConfigurations,
      [](const Configuration& conf, double gap) {
        const auto g = slaveAt(conf.face, conf.xi, gap);
        // Committed traction at 10 % of the cone, along the motion (covariant: ā_αβ Δξ^β direction).
        const auto p = cc::FaceProjection3D::evaluateAt(g.slave, g.master, conf.xi);
        const Vector<2> dxi = cc::subtract(conf.xi, conf.xiN);
        const Vector<2> along = cc::multiply(p.metric, dxi);
        const double length = std::sqrt(cc::dot(dxi, along));
        return std::make_pair(
            g, inContact(7, conf.xiN, cc::scaled(0.1 * 0.3 * 1e3 * std::abs(gap) / length, along), ContactStatus::Stick));
      },
      ct::kFdTolerance, "Quad4");
}

// With two surface coordinates eq. (27) leaves stiffness across the slip direction; the paper's main terms
// alone (eq. 24–26) miss the geometric and curvature terms on a warped face.
TEST(NodeToFacetContactQuad4, PaperMainTermsAloneMissTheGeometricTerms) {
  for (const Case& c : kCases) {
    const Element main(c.parameters, cc::TangentTerms::PaperMainTerms);
    const Element full(c.parameters);
    const Configuration& conf = kConfigurations[2];
    const auto g = slaveAt(conf.face, conf.xi, conf.gap);
    const auto committed = inContact(7, conf.xiN, c.committedTraction, ContactStatus::Stick);
    const Mat fd = ct::finiteDifferenceTangent(full, g, 7, committed, ct::kFdStep);
    const auto rMain = main.evaluate(g, 7, committed);
    const auto rFull = full.evaluate(g, 7, committed);
    EXPECT_GT(ct::relativeDifference(rMain.tangent, fd), 1e-3) << c.law;
    for (int i = 0; i < kN; ++i) EXPECT_EQ(rMain.residual[i], rFull.residual[i]);
    if (c.expected == ContactStatus::Stick || c.parameters.isFrictionless())
      EXPECT_LT(ct::asymmetry(rMain.tangent), 1e-14) << c.law;  // eq. (24), (25) are symmetric
    else
      EXPECT_GT(ct::asymmetry(rMain.tangent), 1e-3) << c.law;  // eq. (26) is not
  }
  // The warped face is curved at the contact point: b̄_12 = x̄,12·n̄ ≠ 0 enters A_αβ and the tangent.
  const Configuration& conf = kConfigurations[2];
  const auto r = Element({1e3, 0.0, 0.0}).evaluate(slaveAt(conf.face, conf.xi, conf.gap), 7, {});
  cc::Vector<3> x12{};
  const auto d2H = Facet::shapeSecondDerivatives(conf.xi);
  for (int i = 0; i < 4; ++i) cc::addScaled(x12, d2H[i](0, 1), conf.face[i]);
  EXPECT_GT(std::abs(cc::dot(x12, r.projection.normal)), 0.05);
}

// Eq. (27) in two coordinates: the slip tangent has no stiffness along the slip direction, the full
// Coulomb stiffness μ|t_N|/‖t^trial‖ ε_T across it; the secant option adds stiffness along the slip only.
TEST(NodeToFacetContactQuad4, SecantSlipTangentChangesOnlyTheTangentAlongTheSlip) {
  const Element element({1e3, 0.0, 0.3, 0.005});
  const double facetLength = 4.0;
  for (const Configuration& conf : kConfigurations) {
    SCOPED_TRACE(conf.name);
    const auto g = slaveAt(conf.face, conf.xi, conf.gap);
    const auto committed = inContact(7, conf.xiN, {0.0, 0.0}, ContactStatus::Slip);
    const auto consistent = element.evaluate(g, 7, committed, facetLength);
    ASSERT_EQ(consistent.status, ContactStatus::Slip);
    const auto secant = element.evaluate(g, 7, committed, facetLength, cc::SlipTangent::secantOf(1.0));
    for (int i = 0; i < kN; ++i) EXPECT_EQ(consistent.residual[i], secant.residual[i]);
    EXPECT_EQ(consistent.trial, secant.trial);
    Mat difference = secant.tangent;
    cc::addScaled(difference, -1.0, consistent.tangent);
    const double size = cc::frobeniusNorm(difference);
    EXPECT_GT(size, 0.0);
    EXPECT_LT(ct::asymmetry(difference), 1e-12);  // k (s·Ξ)(s·Ξ)ᵀ: symmetric, rank one
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j)
        EXPECT_NEAR(difference(i, i) * difference(j, j), difference(i, j) * difference(j, i), 1e-10 * size * size);
  }
}

TEST(NodeToFacetContactQuad4, FrictionOpposesAnObliqueSlipAndKeepsTheCoulombLimit) {
  // Slip along an oblique direction of a skewed face: the friction force on the slave is antiparallel to
  // the physical slip vector ā_α Δξ^α (not to a coordinate axis), with magnitude μ ε_N |g_N|.
  const Element element({1e3, 5e2, 0.3});
  const Configuration& conf = kConfigurations[1];
  const auto g = slaveAt(conf.face, conf.xi, conf.gap);
  const auto r = element.evaluate(g, 7, inContact(7, conf.xiN, {0.0, 0.0}, ContactStatus::Stick));
  ASSERT_EQ(r.status, ContactStatus::Slip);
  const auto& p = r.projection;
  Vector<3> slip{};
  for (int al = 0; al < 2; ++al) cc::addScaled(slip, conf.xi[al] - conf.xiN[al], p.covariantBasis[al]);
  const Vector<3> force = r.slaveForce();
  const Vector<3> tangential = cc::subtract(force, cc::scaled(cc::dot(force, p.normal), p.normal));
  EXPECT_NEAR(cc::dot(force, p.normal), 1e3 * std::abs(conf.gap), 1e-9);  // eq. (16), along +n̄
  EXPECT_NEAR(cc::norm(tangential), 0.3 * 1e3 * std::abs(conf.gap), 1e-9);  // ‖t_T‖ = μ|t_N|, eq. (22)
  EXPECT_NEAR(cc::dot(tangential, slip) / (cc::norm(tangential) * cc::norm(slip)), -1.0, 1e-12);
}

TEST(NodeToFacetContactQuad4, GapAndForcesAreFrameInvariant) {
  // A rigid rotation (and translation) of the whole element rotates the forces and the tangent with it
  // and leaves g_N, ξ̄ and the status unchanged; the forces balance, and so do their moments.
  const double angle = 0.7;
  const Vector<3> axis = cc::scaled(1.0 / std::sqrt(3.0 * 3.0 + 1.0 + 4.0), Vector<3>{3.0, -1.0, 2.0});
  cc::Matrix<3, 3> R;  // Rodrigues
  const double c = std::cos(angle), s = std::sin(angle);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R(i, j) = (i == j ? c : 0.0) + (1.0 - c) * axis[i] * axis[j];
  R(0, 1) -= s * axis[2];
  R(1, 0) += s * axis[2];
  R(0, 2) += s * axis[1];
  R(2, 0) -= s * axis[1];
  R(1, 2) -= s * axis[0];
  R(2, 1) += s * axis[0];
  const Vector<3> shift{0.3, -1.2, 5.0};
  auto move = [&](const Vector<3>& x) { return cc::add(cc::multiply(R, x), shift); };
  const Element element({1e3, 5e2, 0.3});
  for (const Configuration& conf : kConfigurations) {
    SCOPED_TRACE(conf.name);
    const auto g = slaveAt(conf.face, conf.xi, conf.gap);
    Geometry moved{move(g.slave), {}};
    for (int i = 0; i < 4; ++i) moved.master[i] = move(g.master[i]);
    const auto committed = inContact(7, conf.xiN, {0.4, -0.2}, ContactStatus::Stick);
    const auto a = element.evaluate(g, 7, committed);
    const auto b = element.evaluate(moved, 7, committed);
    EXPECT_EQ(a.status, b.status);
    EXPECT_NEAR(a.projection.gap, b.projection.gap, 1e-13);
    EXPECT_NEAR(a.projection.xi[0], b.projection.xi[0], 1e-12);
    EXPECT_NEAR(a.projection.xi[1], b.projection.xi[1], 1e-12);
    double scale = 0.0;
    for (int i = 0; i < kN; ++i) scale = std::max(scale, std::abs(a.residual[i]));
    Vector<3> total{}, moment{};
    for (int node = 0; node < 5; ++node) {
      const Vector<3> ra{a.residual[3 * node], a.residual[3 * node + 1], a.residual[3 * node + 2]};
      const Vector<3> rb{b.residual[3 * node], b.residual[3 * node + 1], b.residual[3 * node + 2]};
      const Vector<3> rotated = cc::multiply(R, ra);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(rotated[k], rb[k], 1e-12 * scale);
      total = cc::add(total, ra);
      const Vector<3> position = node == 0 ? g.slave : g.master[node - 1];
      moment = cc::add(moment, cc::cross(position, ra));
    }
    EXPECT_LT(cc::norm(total), 1e-12 * scale);
    EXPECT_LT(cc::norm(moment), 1e-11 * scale);
    // K_b = (I ⊗ R) K_a (I ⊗ R)ᵀ
    Mat expected{};
    for (int a1 = 0; a1 < 5; ++a1)
      for (int b1 = 0; b1 < 5; ++b1)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            double sum = 0.0;
            for (int k = 0; k < 3; ++k)
              for (int l = 0; l < 3; ++l) sum += R(i, k) * a.tangent(3 * a1 + k, 3 * b1 + l) * R(j, l);
            expected(3 * a1 + i, 3 * b1 + j) = sum;
          }
    EXPECT_LT(ct::relativeDifference(b.tangent, expected), 1e-12);
  }
}

TEST(NodeToFacetContactQuad4, OpenNodeFirstContactAndFacetCheck) {
  const Element element({1e3, 5e2, 0.3});
  const auto open = element.evaluate(slaveAt(kWarped, {0.2, 0.1}, 0.01), 7,
                                     inContact(7, {0.0, 0.0}, {2.0, 1.0}, ContactStatus::Stick));
  EXPECT_EQ(open.status, ContactStatus::Open);
  EXPECT_EQ(open.trial.status, ContactStatus::Open);
  for (int i = 0; i < kN; ++i) EXPECT_EQ(open.residual[i], 0.0);
  EXPECT_EQ(cc::frobeniusNorm(open.tangent), 0.0);

  const auto g = slaveAt(kWarped, {0.4, -0.2}, -0.01);
  const auto first = element.evaluate(g, 3, cc::ContactHistory<2>{});
  EXPECT_EQ(first.status, ContactStatus::Stick);
  EXPECT_EQ(first.tangentialTraction, (Vector<2>{0.0, 0.0}));
  EXPECT_EQ(first.trial.segment, 3);
  EXPECT_NEAR(first.trial.xi[0], 0.4, 1e-12);  // the stick reference point of the next increment
  EXPECT_NEAR(first.trial.xi[1], -0.2, 1e-12);
  const Mat fd = ct::finiteDifferenceTangent(element, g, 3, cc::ContactHistory<2>{}, ct::kFdStep);
  EXPECT_LT(ct::relativeDifference(first.tangent, fd), ct::kFdTolerance);

  EXPECT_THROW(element.evaluate(g, 8, inContact(7, {0.0, 0.0}, {0.0, 0.0}, ContactStatus::Stick)), std::logic_error);

  // Accumulated slip, eq. (7): √(Δξ ā Δξ) on the flat unit-metric face, from ξ_n = (−0.5, 0) to (0.3, 0.6).
  const auto r = element.evaluate(slaveAt(kFlat, {0.3, 0.6}, -0.01), 7,
                                  inContact(7, {-0.5, 0.0}, {0.0, 0.0}, ContactStatus::Stick, 0.25));
  EXPECT_NEAR(r.trial.accumulatedSlip, 0.25 + 1.0, 1e-12);
}

// ---- Newton on a tiny 3D model: springs hold the five nodes, a force presses and drags the slave node
// across the warped face. Quadratic convergence with the consistent tangent, in stick and in slip.
namespace {

std::vector<double> newtonHistory(const cc::ContactLawParameters& law, cc::TangentTerms terms, ContactStatus* status) {
  const Element element(law, terms);
  const auto start = slaveAt(kWarped, {0.1, -0.2}, -0.002);
  const Vec reference = ct::toDofs(start);
  Vec force{};
  force[0] = 3.0;
  force[1] = -2.0;
  force[2] = -8.0;  // mostly into the face (n̄ ≈ +z), and obliquely along it
  const double spring = 40.0;
  const auto committed = inContact(7, {0.1, -0.2}, {0.0, 0.0}, ContactStatus::Stick);
  Vec x = reference;
  std::vector<double> norms;
  for (int it = 0; it < 40; ++it) {
    const auto r = element.evaluate(ct::fromDofs<Facet>(x), 7, committed, 2.0);  // L_k = the face size
    *status = r.status;
    Vec residual{};
    Mat k = r.tangent;
    for (int i = 0; i < kN; ++i) {
      residual[i] = spring * (x[i] - reference[i]) + r.residual[i] - force[i];
      k(i, i) += spring;
    }
    norms.push_back(cc::norm(residual));
    if (norms.back() < 1e-11) break;
    const Vec dx = ct::solve(k, residual);
    for (int i = 0; i < kN; ++i) x[i] -= dx[i];
  }
  return norms;
}

void expectQuadratic(const std::vector<double>& norms) {
  ASSERT_LT(norms.back(), 1e-11);
  EXPECT_LE(norms.size(), 9u);
  const std::size_t n = norms.size();
  ASSERT_GE(n, 3u);
  // r_{k+1} ≤ C r_k² in the asymptotic range
  EXPECT_LT(norms[n - 2], 10.0 * norms[n - 3] * norms[n - 3] + 1e-11);
}

}  // namespace

TEST(NodeToFacetContactQuad4, ConsistentTangentGivesQuadraticNewtonConvergence) {
  ContactStatus status = ContactStatus::Open;
  for (const auto& [name, law, expected] :
       {std::tuple{"stick", cc::ContactLawParameters{1e3, 5e2, 5.0}, ContactStatus::Stick},
        std::tuple{"slip", cc::ContactLawParameters{1e3, 5e2, 0.2}, ContactStatus::Slip},
        std::tuple{"slip, slip tolerance", cc::ContactLawParameters{1e3, 0.0, 0.2, 0.005}, ContactStatus::Slip}}) {
    SCOPED_TRACE(name);
    const auto consistent = newtonHistory(law, cc::TangentTerms::Consistent, &status);
    EXPECT_EQ(status, expected);
    std::printf("[ Newton   ] %-22s", name);
    for (double v : consistent) std::printf(" %.1e", v);
    std::printf("\n");
    expectQuadratic(consistent);
    const auto paper = newtonHistory(law, cc::TangentTerms::PaperMainTerms, &status);
    std::printf("[ Newton   ] %-22s paper main terms: %zu iterations, last %.1e\n", name, paper.size(), paper.back());
    EXPECT_GT(paper.size(), consistent.size());
  }
}
