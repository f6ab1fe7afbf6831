#include "model/JacobianCheck.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include <Teuchos_CommHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

namespace contessa::model {

using Teuchos::RCP;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;

namespace {

// The residual f(x, λ) into `f`.
void residual(const ContactMechanicsModel& model, const RCP<const Thyra::VectorBase<double>>& x, double lambda,
              const RCP<Thyra::VectorBase<double>>& f) {
  auto in = model.createInArgs();
  auto p = Thyra::createMember(model.get_p_space(0));
  Thyra::set_ele(0, lambda, p.ptr());
  in.set_x(x);
  in.set_p(0, p);
  auto out = model.createOutArgs();
  out.set_f(f);
  model.evalModel(in, out);
}

// The largest bend of a compared column: h |f''| / 2 against an entry's scale, about the ratio of the step
// to the length over which the residual's slope changes by its own size. Where f''' is of the size
// f'' / length, the central difference's error is about (2 · bend)² / 6 of the entry, but f'' can be
// small where f''' is not (with a pressure-dependent slip tolerance a bend of 9e-4 came with an error of
// 2.6e-4): above this bend the column is differenced again and the two steps decide (kAgreement).
constexpr double kMaxBend = 1e-4;
// The bend a shortened step aims at, about a quarter of this (an error ~1e-7 where f''' ~ f'' / length):
// no shorter than needed, since the floor of an entry's scale grows as the step shrinks.
constexpr double kShortStepBend = 1e-3;
// Differences at two steps that agree to this fraction of an entry's scale (at the longer step): the
// longer step's are accurate to about as much (the error of a central difference falls as h²).
constexpr double kAgreement = 1e-5;

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The contact trial state, as far as the model shows it (gaps, status, Coulomb indicator of the latest
// evaluation), must be what
// it was before the check: the perturbed residuals leave no trace.
void requireSameContactState(const std::vector<continuation::SlaveNodeIncrement>& before,
                             const std::vector<continuation::SlaveNodeIncrement>& after) {
  bool same = before.size() == after.size();
  for (std::size_t k = 0; same && k < before.size(); ++k)
    same = sameBits(before[k].committedGap, after[k].committedGap) && sameBits(before[k].trialGap, after[k].trialGap) &&
           before[k].trialStatus == after[k].trialStatus && sameBits(before[k].trialIndicator, after[k].trialIndicator) &&
           before[k].slipReversed == after[k].slipReversed && before[k].trialFacet == after[k].trialFacet;
  if (!same) throw std::logic_error("the Jacobian check changed the contact trial state of the model");
}

// Central differences of f, column by column (every rank walks all global columns in the same order;
// the owner of column j perturbs it), against the entries of W on this rank's rows.
JacobianComparison compareAt(const ContactMechanicsModel& model, const Thyra::VectorBase<double>& x, double lambda,
                             const Thyra::LinearOpBase<double>& W, const JacobianCheck::Options& options) {
  const auto start = std::chrono::steady_clock::now();
  auto matrix = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(Teuchos::rcpFromRef(W)), true);
  const auto& rowMap = *matrix->getRowMap();
  const auto& colMap = *matrix->getColMap();
  const auto comm = rowMap.getComm();
  const LO numRows = static_cast<LO>(rowMap.getNodeNumElements());

  // W by columns on this rank's rows, and each row's largest entry.
  std::unordered_map<GO, std::vector<std::pair<LO, double>>> columns;
  std::vector<double> rowMax(numRows, 0.0);
  for (LO r = 0; r < numRows; ++r) {
    CrsMatrix::local_inds_host_view_type indices;
    CrsMatrix::values_host_view_type values;
    matrix->getLocalRowView(r, indices, values);
    for (std::size_t k = 0; k < indices.extent(0); ++k) {
      columns[colMap.getGlobalElement(indices(k))].emplace_back(r, values(k));
      rowMax[r] = std::max(rowMax[r], std::abs(values(k)));
    }
  }

  auto xp = x.clone_v();
  auto xt = Extract::getTpetraVector(xp);
  if (!xt->getMap()->isSameAs(rowMap)) throw std::logic_error("JacobianCheck: W's rows are not distributed as x");
  const double xNorm = xt->normInf();
  auto fPlus = Thyra::createMember(model.get_f_space()), fMinus = Thyra::createMember(model.get_f_space());
  auto fCentre = Thyra::createMember(model.get_f_space()), fHalf = Thyra::createMember(model.get_f_space());
  const auto fh = Extract::getConstTpetraVector(fHalf);
  const auto fp = Extract::getConstTpetraVector(fPlus), fm = Extract::getConstTpetraVector(fMinus);
  residual(model, xp, lambda, fCentre);
  const auto f0 = Extract::getConstTpetraVector(fCentre)->getData(0);

  // The contact status of every slave node (open/stick/slip, slip reversed, and the master facet it is
  // evaluated on) at the unperturbed state: W is the derivative of the residual with these held. A
  // perturbed residual whose statuses differ lies beyond a kink of the residual (a node opening or
  // closing, stick turning to slip, a node at a vertex changing facet), where no difference quotient
  // measures W.
  const auto statusesOf = [&model]() {
    std::vector<int> s;
    for (const auto& n : model.trialIncrement()) {
      s.push_back(2 * static_cast<int>(n.trialStatus) + (n.slipReversed ? 1 : 0));
      s.push_back(n.trialFacet);
    }
    return s;
  };
  const std::vector<int> baseStatuses = statusesOf();
  const auto sameStatusesEverywhere = [&]() {
    int same = statusesOf() == baseStatuses ? 1 : 0, all = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, 1, &same, &all);
    return all == 1;
  };

  JacobianComparison result;
  result.residualEvaluations = 1;
  double localWorst = -1, worstW = 0, worstD = 0, sums[2] = {0, 0};  // Σ (W − D)², Σ W²
  GO worstRow = -1, worstColumn = -1;
  std::vector<double> wColumn(numRows, 0.0), differences(numRows, 0.0), scales(numRows, 0.0);
  std::vector<double> previousDifferences(numRows, 0.0), previousScales(numRows, 0.0);
  const GO first = rowMap.getMinAllGlobalIndex(), last = rowMap.getMaxAllGlobalIndex();
  for (GO j = first; j <= last; ++j) {
    const LO lj = rowMap.getLocalElement(j);
    const bool mine = lj != Teuchos::OrdinalTraits<LO>::invalid();
    double xj = 0, h = 0, hLocal = 0;
    if (mine) {
      xj = xt->getData(0)[lj];
      hLocal = options.step * std::max({std::abs(xj), xNorm, 1.0});
    }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &hLocal, &h);
    if (h == 0) continue;  // no rank has this DOF
    const auto found = columns.find(j);
    if (found != columns.end())
      for (const auto& [r, w] : found->second) wColumn[r] = w;
    // f(x ± h e_j), the same h on every rank; the perturbed value rounded, so the step is exactly the
    // one taken. A side whose contact statuses differ from the unperturbed ones is not used; when both
    // differ, h shrinks (by kStepShrink, kKinkShrinks times) before the column is given up as non-smooth.
    // Where the residual bends within the step (see kMaxBend), h shrinks until it does not.
    constexpr int kKinkShrinks = 2, kBendShrinks = 2;
    constexpr double kStepShrink = 1e-2;
    double shrink = 1;
    int kinkShrinks = 0, bendShrinks = 0;
    bool compared = false, havePrevious = false, counted = false;
    for (;;) {
      double taken[2] = {0, 0}, steps[2] = {0, 0};
      bool smooth[2] = {false, false};
      for (int side = 0; side < 2; ++side) {
        if (mine) {
          auto v = xt->getDataNonConst(0);
          v[lj] = side == 0 ? xj + shrink * h : xj - shrink * h;
          steps[side] = std::abs(v[lj] - xj);
        }
        residual(model, xp, lambda, side == 0 ? fPlus : fMinus);
        smooth[side] = sameStatusesEverywhere();
      }
      if (mine) xt->getDataNonConst(0)[lj] = xj;
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 2, steps, taken);
      result.residualEvaluations += 2;
      if (!smooth[0] && !smooth[1]) {
        if (havePrevious) {  // a kink within the shorter step: the longer one's differences stand
          differences.swap(previousDifferences);
          scales.swap(previousScales);
          compared = true;
          break;
        }
        if (kinkShrinks++ < kKinkShrinks) {
          shrink *= kStepShrink;
          continue;
        }
        break;
      }
      // One side only: the one-sided difference is second-order accurate with a half step added on that
      // side, D = [b²(f_a − f_0) − a²(f_b − f_0)] / (a b (b − a)) for the signed steps a ≈ b/2 and b (a
      // first-order one would carry an error of h·f''/2, as large as the check's tolerance).
      const int side = smooth[0] ? 0 : 1;
      double halfTaken = 0;
      bool halfSmooth = false;
      if (!(smooth[0] && smooth[1])) {
        double halfStep = 0;
        if (mine) {
          auto v = xt->getDataNonConst(0);
          v[lj] = side == 0 ? xj + 0.5 * shrink * h : xj - 0.5 * shrink * h;
          halfStep = std::abs(v[lj] - xj);
        }
        residual(model, xp, lambda, fHalf);
        halfSmooth = sameStatusesEverywhere();
        if (mine) xt->getDataNonConst(0)[lj] = xj;
        Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &halfStep, &halfTaken);
        ++result.residualEvaluations;
      }
      const double sign = side == 0 ? 1.0 : -1.0, stepA = sign * halfTaken, stepB = sign * taken[side];
      const auto a = fp->getData(0), b = fm->getData(0), half = fh->getData(0);
      // Central differences where both sides keep the statuses, else the one-sided difference on the
      // side that does; with each, the second difference f'' of the same residuals, and the bend of the
      // column: max over rows of h |f''| / 2 (the error of a one-sided first-order difference) against
      // the entry's scale (below).
      double bend = 0;
      for (LO r = 0; r < numRows; ++r) {
        const double fb = side == 0 ? a[r] : b[r];
        double d = 0, second = 0;
        if (smooth[0] && smooth[1]) {
          d = (a[r] - b[r]) / (taken[0] + taken[1]);
          second = 2 * ((a[r] - f0[r]) / taken[0] - (f0[r] - b[r]) / taken[1]) / (taken[0] + taken[1]);
        } else if (halfSmooth) {
          d = (stepB * stepB * (half[r] - f0[r]) - stepA * stepA * (fb - f0[r])) / (stepA * stepB * (stepB - stepA));
          second = 2 * ((fb - f0[r]) / stepB - (half[r] - f0[r]) / stepA) / (stepB - stepA);
        } else {
          d = (fb - f0[r]) / stepB;
        }
        // The noise of a difference grows as 1/h: a shrunk step raises the floor in proportion.
        const double scale = std::max(std::abs(wColumn[r]), options.rowFloor * rowMax[r] / shrink);
        differences[r] = d;
        scales[r] = scale;
        if (scale > 0) bend = std::max(bend, 0.5 * taken[side] * std::abs(second) / scale);
      }
      double globalBend = 0;
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &bend, &globalBend);
      if (havePrevious) {
        // The differences at the longer step against these: where they agree, the bend did no harm (f'''
        // small: an entry whose slope is small against its curvature), and the longer step's
        // differences, with the lower floor, stand.
        double disagreement = 0, globalDisagreement = 0;
        for (LO r = 0; r < numRows; ++r) {
          const double gap = std::abs(previousDifferences[r] - differences[r]);
          if (gap > 0) disagreement = std::max(disagreement, previousScales[r] > 0 ? gap / previousScales[r] : gap);
          if (!std::isfinite(gap)) disagreement = std::numeric_limits<double>::infinity();
        }
        Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &disagreement, &globalDisagreement);
        if (globalDisagreement <= kAgreement) {
          differences.swap(previousDifferences);
          scales.swap(previousScales);
          compared = true;
          break;
        }
        if (!counted) ++result.bentColumns;
        counted = true;
      }
      // A residual that bends within the step (the slip direction of a 3D frictional node turns by
      // ε_T h / ‖t^trial‖, which is not small when ‖t^trial‖ is a few times μ|t_N|): the central
      // difference's error can reach (2·bend)²/6 of the entry, or more. Difference again with h shrunk so
      // the bend is about kShortStepBend / 4 (at least tenfold), and keep the shorter step unless both
      // agree (above).
      if (std::isfinite(globalBend) && globalBend > kMaxBend && bendShrinks++ < kBendShrinks) {
        previousDifferences = differences;
        previousScales = scales;
        if (!havePrevious) ++result.retriedColumns;
        havePrevious = true;
        shrink *= std::clamp(0.25 * kShortStepBend / globalBend, 1e-4, 0.1);
        continue;
      }
      compared = true;
      break;
    }
    if (!compared) {
      if (result.nonSmoothColumns++ == 0) result.firstNonSmoothColumn = j;
    } else {
      for (LO r = 0; r < numRows; ++r) {
        const double w = wColumn[r], d = differences[r], scale = scales[r];
        if (w == 0 && d == 0) continue;
        const double difference = std::abs(w - d);
        double e = std::numeric_limits<double>::infinity();
        if (std::isfinite(d)) e = scale > 0 ? difference / scale : (difference > 0 ? e : 0.0);
        sums[0] += std::isfinite(d) ? difference * difference : 0.0;
        sums[1] += w * w;
        if (e > localWorst) {
          localWorst = e;
          worstRow = rowMap.getGlobalElement(r);
          worstColumn = j;
          worstW = w;
          worstD = d;
        }
      }
    }
    if (found != columns.end())
      for (const auto& [r, w] : found->second) wColumn[r] = 0.0;
  }

  // The worst entry over the ranks: the largest error, then the lowest (row, column).
  double global = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &localWorst, &global);
  const long long none = std::numeric_limits<long long>::max();
  const long long span = static_cast<long long>(last) + 1;
  long long key = localWorst == global && worstRow >= 0 ? worstRow * span + worstColumn : none, globalKey = none;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, 1, &key, &globalKey);
  double values[2] = {key == globalKey ? worstW : 0.0, key == globalKey ? worstD : 0.0}, globalValues[2];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 2, values, globalValues);
  double globalSums[2];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 2, sums, globalSums);
  result.worstRelativeError = std::max(global, 0.0);
  if (globalKey != none) {
    result.row = globalKey / span;
    result.column = globalKey % span;
  }
  result.assembled = globalValues[0];
  result.finiteDifference = globalValues[1];
  result.normwiseError = globalSums[1] > 0 ? std::sqrt(globalSums[0] / globalSums[1]) : std::sqrt(globalSums[0]);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &seconds, &result.seconds);
  return result;
}

}  // namespace

JacobianComparison JacobianCheck::compare(const ContactMechanicsModel& model, const Thyra::VectorBase<double>& x,
                                          double lambda, const Thyra::LinearOpBase<double>& W) const {
  const auto state = model.saveEvaluationState();
  const auto gaps = model.trialIncrement();
  const auto result = compareAt(model, x, lambda, W, options_);
  model.restoreEvaluationState(*state);
  requireSameContactState(gaps, model.trialIncrement());
  return result;
}

JacobianComparison JacobianCheck::check(const ContactMechanicsModel& model, const Thyra::VectorBase<double>& x,
                                        double lambda) const {
  const auto state = model.saveEvaluationState();
  const auto gaps = model.trialIncrement();
  auto W = model.create_W_op();
  {
    auto in = model.createInArgs();
    auto p = Thyra::createMember(model.get_p_space(0));
    Thyra::set_ele(0, lambda, p.ptr());
    in.set_x(Teuchos::rcpFromRef(x));
    in.set_p(0, p);
    auto out = model.createOutArgs();
    out.set_W_op(W);
    model.evalModel(in, out);
  }
  const auto result = compareAt(model, x, lambda, *W, options_);
  model.restoreEvaluationState(*state);
  requireSameContactState(gaps, model.trialIncrement());
  return result;
}

std::string JacobianCheck::describe(const JacobianComparison& r, const ContactMechanicsModel& model) {
  const int dim = model.dimension();
  const auto dof = [dim](GO g) {
    // Node numbers are Exodus ids (1-based), as in the output file.
    return "node " + std::to_string(g / dim + 1) + " " + std::string(1, "xyz"[g % dim]);
  };
  char text[512];
  if (r.row < 0)
    std::snprintf(text, sizeof text, "worst relative error 0 (W and its finite differences agree exactly)");
  else
    std::snprintf(text, sizeof text,
                "worst relative error %.1e at row %s, column %s (%s), W = %.4g, FD = %.4g; "
                "norm-wise ||W - W_FD||/||W|| = %.1e",
                r.worstRelativeError, dof(r.row).c_str(), dof(r.column).c_str(),
                model.describeCoupling(r.row, r.column).c_str(), r.assembled, r.finiteDifference, r.normwiseError);
  std::string line = text;
  if (r.nonSmoothColumns > 0)
    line += "; " + std::to_string(r.nonSmoothColumns) + " column(s) not compared (a contact status changes within ±h on both sides, " +
            "first: " + dof(r.firstNonSmoothColumn) + ")";
  if (r.bentColumns > 0)
    line += "; " + std::to_string(r.bentColumns) + " column(s) differenced with a shorter step (the residual bends within h)";
  return line;
}

}  // namespace contessa::model
