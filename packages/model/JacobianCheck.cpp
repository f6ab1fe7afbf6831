#include "model/JacobianCheck.hpp"

#include <algorithm>
#include <array>
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
           before[k].slipReversed == after[k].slipReversed && before[k].trialFacet == after[k].trialFacet &&
           before[k].trialContactKind == after[k].trialContactKind &&
           before[k].trialContactNodes[0] == after[k].trialContactNodes[0] &&
           before[k].trialContactNodes[1] == after[k].trialContactNodes[1];
  if (!same) throw std::logic_error("the Jacobian check changed the contact trial state of the model");
}

// W by columns on this rank's rows (global column id → (local row, W_ij)), and each row's largest
// |entry|: the scale of the floor τ · max_k |W_ik| below which an entry is measured against the floor.
struct AssembledColumns {
  std::unordered_map<GO, std::vector<std::pair<LO, double>>> entries;
  std::vector<double> rowMax;
};

AssembledColumns assembledColumns(const CrsMatrix& matrix) {
  const auto& colMap = *matrix.getColMap();
  const LO numRows = static_cast<LO>(matrix.getRowMap()->getNodeNumElements());
  AssembledColumns w;
  w.rowMax.assign(numRows, 0.0);
  for (LO r = 0; r < numRows; ++r) {
    CrsMatrix::local_inds_host_view_type indices;
    CrsMatrix::values_host_view_type values;
    matrix.getLocalRowView(r, indices, values);
    for (std::size_t k = 0; k < indices.extent(0); ++k) {
      w.entries[colMap.getGlobalElement(indices(k))].emplace_back(r, values(k));
      w.rowMax[r] = std::max(w.rowMax[r], std::abs(values(k)));
    }
  }
  return w;
}

// The unknown x_j a column perturbs: its owner rank holds it (`mine`, local index lj, value xj); the
// step h is the same on every rank.
struct Column {
  LO lj = 0;
  bool mine = false;
  double xj = 0, h = 0;
};

// What of the contact state a perturbed residual changed, one flag each (kKinds of them): a node's status
// (open/stick/slip, slip reversed), its master facet, its contact point on the facet (the projection, an
// edge point or a vertex and which, the projection past a free edge: SlaveNodeIncrement::trialContactKind).
enum ContactChange { kStatusChange = 0, kFacetChange = 1, kContactPointChange = 2, kKinds = 3 };
using Changes = std::array<int, kKinds>;  // 1 where that part of some node's state changed
bool held(const Changes& c) { return c[kStatusChange] == 0 && c[kFacetChange] == 0 && c[kContactPointChange] == 0; }

// The parts of the contact state that W holds, node by node: each change of one is a kink of the residual.
struct ContactKeys {
  std::vector<int> status, facet, point;
};

ContactKeys contactKeys(const std::vector<continuation::SlaveNodeIncrement>& nodes) {
  ContactKeys keys;
  for (const auto& n : nodes) {
    keys.status.push_back(2 * static_cast<int>(n.trialStatus) + (n.slipReversed ? 1 : 0));
    keys.facet.push_back(n.trialFacet);
    // Where an open node would touch carries no force: only a node in contact has a contact point.
    const bool touching = n.trialStatus != continuation::NodeStatus::Open;
    keys.point.insert(keys.point.end(), {touching ? n.trialContactKind : -1, touching ? n.trialContactNodes[0] : -1,
                                         touching ? n.trialContactNodes[1] : -1});
  }
  return keys;
}

// The residual at x with one unknown moved, on every rank at once, and which parts of the contact state
// held there. The contact state of every slave node (open/stick/slip, slip reversed, the master facet it
// is evaluated on, and its contact point on that facet) at the unperturbed state is what W is the
// derivative with: a perturbed residual whose state differs lies beyond a kink of the residual (a node
// opening or closing, stick turning to slip, a node at a vertex changing facet, a node exactly under an
// edge of two coplanar facets touching the edge point once a step tilts them into a ridge), where no
// difference quotient measures W.
class PerturbedResiduals {
 public:
  PerturbedResiduals(const ContactMechanicsModel& model, const Thyra::VectorBase<double>& x, double lambda,
                     const Map& rowMap)
      : model_(model), lambda_(lambda), rowMap_(rowMap), xp_(x.clone_v()), xt_(Extract::getTpetraVector(xp_)) {
    if (!xt_->getMap()->isSameAs(rowMap)) throw std::logic_error("JacobianCheck: W's rows are not distributed as x");
    xNorm_ = xt_->normInf();
    centre_ = Thyra::createMember(model.get_f_space());
    // f(x) puts every slave node on its facet and contact point; held from here on (the branch W is the
    // derivative on: the header), f(x) again on that branch (the same but for a node past a free edge by
    // round-off, held unfaded).
    residual(model_, xp_, lambda_, centre_);
    model_.holdContactPoints(true);
    residual(model_, xp_, lambda_, centre_);
    base_ = contactKeys(model_.trialIncrement());
  }
  ~PerturbedResiduals() { model_.holdContactPoints(false); }
  PerturbedResiduals(const PerturbedResiduals&) = delete;
  PerturbedResiduals& operator=(const PerturbedResiduals&) = delete;

  const Teuchos::Comm<int>& comm() const { return *rowMap_.getComm(); }
  long evaluations() const { return evaluations_; }
  /// f(x), unperturbed.
  Teuchos::ArrayRCP<const double> centre() const { return Extract::getConstTpetraVector(centre_)->getData(0); }

  /// Column j with its step h_j = η · max(|x_j|, ‖x‖_∞, 1): the owner's, on every rank (0 when no
  /// rank has the DOF).
  Column column(GO j, double step) const {
    Column c;
    c.lj = rowMap_.getLocalElement(j);
    c.mine = c.lj != Teuchos::OrdinalTraits<LO>::invalid();
    double hLocal = 0;
    if (c.mine) {
      c.xj = xt_->getData(0)[c.lj];
      hLocal = step * std::max({std::abs(c.xj), xNorm_, 1.0});
    }
    Teuchos::reduceAll(comm(), Teuchos::REDUCE_MAX, 1, &hLocal, &c.h);
    return c;
  }

  /// f(x ± factor·h e_j) into `f` (side 0: +, side 1: −), x_j set back afterwards. The perturbed value
  /// is rounded, so the step is exactly the one taken: `step` is |x_j' − x_j| on the owner rank, 0
  /// elsewhere. Returns what of the contact state changed on some rank (all 0: the unperturbed state).
  Changes evaluate(const Column& c, int side, double factor, const RCP<Thyra::VectorBase<double>>& f, double& step) {
    step = 0;
    if (c.mine) {
      auto v = xt_->getDataNonConst(0);
      v[c.lj] = side == 0 ? c.xj + factor * c.h : c.xj - factor * c.h;
      step = std::abs(v[c.lj] - c.xj);
    }
    residual(model_, xp_, lambda_, f);
    ++evaluations_;
    const Changes changes = changesEverywhere();
    if (c.mine) xt_->getDataNonConst(0)[c.lj] = c.xj;
    return changes;
  }

 private:
  Changes changesEverywhere() const {
    const ContactKeys now = contactKeys(model_.trialIncrement());
    const Changes local{now.status != base_.status ? 1 : 0, now.facet != base_.facet ? 1 : 0,
                        now.point != base_.point ? 1 : 0};
    Changes all{};
    Teuchos::reduceAll(comm(), Teuchos::REDUCE_MAX, static_cast<int>(kKinds), local.data(), all.data());
    return all;
  }

  const ContactMechanicsModel& model_;
  const double lambda_;
  const Map& rowMap_;
  RCP<Thyra::VectorBase<double>> xp_;
  RCP<Vector> xt_;
  double xNorm_ = 0;
  RCP<Thyra::VectorBase<double>> centre_;
  ContactKeys base_;
  long evaluations_ = 2;  // f(x), before and after the hold
};

// One column's difference quotients D_ij on this rank's rows and the scale each entry is measured
// against.
struct ColumnDifferences {
  std::vector<double> differences, scales;
};

// The residuals of one attempt at a column: f(x + h e_j) and f(x − h e_j) and, when only one side
// keeps the statuses, f at half the step on that side (which must keep them too for that side to count).
struct Attempt {
  double taken[2] = {0, 0};  ///< the steps taken on each side, the same on every rank
  bool smooth[2] = {false, false};
  Changes changes[2] = {};   ///< what of the contact state changed on each side
  double halfTaken = 0;
  bool halfSmooth = false;
};

// Central differences where both sides keep the statuses, else the one-sided difference on the side
// that does; with each, the second difference f'' of the same residuals. Returns the bend of the
// column on this rank: max over rows of h |f''| / 2 (the error of a one-sided first-order difference)
// against the entry's scale.
//
// One side only: the one-sided difference is second-order accurate with a half step added on that
// side, D = [b²(f_a − f_0) − a²(f_b − f_0)] / (a b (b − a)) for the signed steps a ≈ b/2 and b (a
// first-order one would carry an error of h·f''/2, as large as the check's tolerance).
double differenceRows(const Attempt& attempt, const Teuchos::ArrayRCP<const double>& f0,
                      const Teuchos::ArrayRCP<const double>& a, const Teuchos::ArrayRCP<const double>& b,
                      const Teuchos::ArrayRCP<const double>& half, const std::vector<double>& wColumn,
                      const std::vector<double>& rowMax, double rowFloor, double shrink, ColumnDifferences& out) {
  const int side = attempt.smooth[0] ? 0 : 1;
  const double* taken = attempt.taken;
  const double sign = side == 0 ? 1.0 : -1.0, stepA = sign * attempt.halfTaken, stepB = sign * taken[side];
  const bool central = attempt.smooth[0] && attempt.smooth[1];
  double bend = 0;
  for (std::size_t r = 0; r < wColumn.size(); ++r) {
    const double fb = side == 0 ? a[r] : b[r];
    double d = 0, second = 0;
    if (central) {
      d = (a[r] - b[r]) / (taken[0] + taken[1]);
      second = 2 * ((a[r] - f0[r]) / taken[0] - (f0[r] - b[r]) / taken[1]) / (taken[0] + taken[1]);
    } else {  // one side, its half step on the same branch (ColumnDifferencer::evaluate)
      d = (stepB * stepB * (half[r] - f0[r]) - stepA * stepA * (fb - f0[r])) / (stepA * stepB * (stepB - stepA));
      second = 2 * ((fb - f0[r]) / stepB - (half[r] - f0[r]) / stepA) / (stepB - stepA);
    }
    // The noise of a difference grows as 1/h: a shrunk step raises the floor in proportion.
    const double scale = std::max(std::abs(wColumn[r]), rowFloor * rowMax[r] / shrink);
    out.differences[r] = d;
    out.scales[r] = scale;
    if (scale > 0) bend = std::max(bend, 0.5 * taken[side] * std::abs(second) / scale);
  }
  return bend;
}

// How far the differences at a shorter step moved from those at the longer one, against the longer
// step's scales (max over this rank's rows; infinite when one is not finite).
double disagreement(const ColumnDifferences& longer, const ColumnDifferences& shorter) {
  double worst = 0;
  for (std::size_t r = 0; r < longer.differences.size(); ++r) {
    const double gap = std::abs(longer.differences[r] - shorter.differences[r]);
    if (gap > 0) worst = std::max(worst, longer.scales[r] > 0 ? gap / longer.scales[r] : gap);
    if (!std::isfinite(gap)) worst = std::numeric_limits<double>::infinity();
  }
  return worst;
}

// Differences one column of W at a step that shrinks at kinks and bends (the header's rules).
class ColumnDifferencer {
 public:
  ColumnDifferencer(const ContactMechanicsModel& model, PerturbedResiduals& residuals, const std::vector<double>& rowMax,
                    const JacobianCheck::Options& options)
      : residuals_(residuals), rowMax_(rowMax), options_(options), f0_(residuals.centre()),
        previous_{std::vector<double>(rowMax.size(), 0.0), std::vector<double>(rowMax.size(), 0.0)} {
    for (auto* f : {&plus_, &minus_, &half_}) *f = Thyra::createMember(model.get_f_space());
  }

  /// The differences that stand into `out`; false when the column straddles kinks at every step tried
  /// (not compared). Counts retried, bent, one-sided and not compared columns in `result`, the last two
  /// by what changed (ContactChange).
  bool difference(const Column& column, const std::vector<double>& wColumn, JacobianComparison& result,
                  ColumnDifferences& out) {
    straddled_ = {};
    const bool compared = differenceColumn(column, wColumn, result, out);
    const Changes& changes = compared ? standingOneSide_ : straddled_;
    if (compared && held(changes)) return true;
    if (compared) ++result.oneSidedColumns;
    for (int c = 0; c < kKinds; ++c)
      if (changes[c] != 0) ++(compared ? result.oneSidedFor : result.nonSmoothFor)[c];
    return compared;
  }

 private:
  bool differenceColumn(const Column& column, const std::vector<double>& wColumn, JacobianComparison& result,
                        ColumnDifferences& out) {
    // A side whose contact statuses differ from the unperturbed ones is not used; when both differ, h
    // shrinks (by kStepShrink, kKinkShrinks times) before the column is given up as non-smooth. Where
    // the residual bends within the step (see kMaxBend), h shrinks until it does not.
    constexpr int kKinkShrinks = 2, kBendShrinks = 2;
    constexpr double kStepShrink = 1e-2;
    double shrink = 1;
    int kinkShrinks = 0, bendShrinks = 0;
    bool havePrevious = false, counted = false;
    for (;;) {
      const Attempt attempt = evaluate(column, shrink);
      if (!attempt.smooth[0] && !attempt.smooth[1]) {
        for (const auto& side : attempt.changes)
          for (int c = 0; c < kKinds; ++c) straddled_[c] = std::max(straddled_[c], side[c]);
        if (havePrevious) {  // a kink within the shorter step: the longer one's differences stand
          standPrevious(out);
          return true;
        }
        if (kinkShrinks++ < kKinkShrinks) {
          shrink *= kStepShrink;
          continue;
        }
        return false;
      }
      double bend = differenceRows(attempt, f0_, data(plus_), data(minus_), data(half_), wColumn, rowMax_,
                                   options_.rowFloor, shrink, out);
      standingOneSide_ = attempt.smooth[0] == attempt.smooth[1] ? Changes{} : attempt.changes[attempt.smooth[0] ? 1 : 0];
      double globalBend = 0;
      Teuchos::reduceAll(residuals_.comm(), Teuchos::REDUCE_MAX, 1, &bend, &globalBend);
      if (havePrevious) {
        // The differences at the longer step against these: where they agree, the bend did no harm (f'''
        // small: an entry whose slope is small against its curvature), and the longer step's
        // differences, with the lower floor, stand.
        double local = disagreement(previous_, out), global = 0;
        Teuchos::reduceAll(residuals_.comm(), Teuchos::REDUCE_MAX, 1, &local, &global);
        if (global <= kAgreement) {
          standPrevious(out);
          return true;
        }
        if (!counted) ++result.bentColumns;
        counted = true;
      }
      // A residual that bends within the step (the slip direction of a 3D frictional node turns by
      // ε_T h / ‖t^trial‖, which is not small when ‖t^trial‖ is a few times μ|t_N|): the central
      // difference's error can reach (2·bend)²/6 of the entry, or more. Difference again with h shrunk
      // so the bend is about kShortStepBend / 4 (at least tenfold), and keep the shorter step unless
      // both agree (above).
      if (std::isfinite(globalBend) && globalBend > kMaxBend && bendShrinks++ < kBendShrinks) {
        previous_.differences = out.differences;
        previous_.scales = out.scales;
        previousOneSide_ = standingOneSide_;
        if (!havePrevious) ++result.retriedColumns;
        havePrevious = true;
        shrink *= std::clamp(0.25 * kShortStepBend / globalBend, 1e-4, 0.1);
        continue;
      }
      return true;
    }
  }

  static Teuchos::ArrayRCP<const double> data(const RCP<Thyra::VectorBase<double>>& f) {
    return Extract::getConstTpetraVector(f)->getData(0);
  }

  // The longer step's differences stand: they go to `out` (and out's to the spare, reused next column).
  void standPrevious(ColumnDifferences& out) {
    out.differences.swap(previous_.differences);
    out.scales.swap(previous_.scales);
    standingOneSide_ = previousOneSide_;
  }

  // f(x ± shrink·h e_j), and where only one side keeps the statuses, the half step on that side.
  Attempt evaluate(const Column& column, double shrink) {
    Attempt attempt;
    double steps[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      attempt.changes[side] = residuals_.evaluate(column, side, shrink, side == 0 ? plus_ : minus_, steps[side]);
      attempt.smooth[side] = held(attempt.changes[side]);
    }
    Teuchos::reduceAll(residuals_.comm(), Teuchos::REDUCE_MAX, 2, steps, attempt.taken);
    if (attempt.smooth[0] != attempt.smooth[1]) {
      const int side = attempt.smooth[0] ? 0 : 1;
      double halfStep = 0;
      const Changes half = residuals_.evaluate(column, side, 0.5 * shrink, half_, halfStep);
      attempt.halfSmooth = held(half);
      Teuchos::reduceAll(residuals_.comm(), Teuchos::REDUCE_MAX, 1, &halfStep, &attempt.halfTaken);
      // The state changes between the step and its half on the side that kept it: a node that round-off
      // moves from one branch to another and back (one under the edge of two coplanar facets, evaluated on
      // either). That side is no smooth stretch of the residual either, and the first-order difference it
      // would leave was 0.2 off on a column whose branch bends (the 3D stick patch, docs/user-guide.md):
      // the column straddles kinks on both sides.
      if (!attempt.halfSmooth) {
        attempt.smooth[side] = false;
        attempt.changes[side] = half;
      }
    }
    return attempt;
  }

  PerturbedResiduals& residuals_;
  const std::vector<double>& rowMax_;
  const JacobianCheck::Options& options_;
  const Teuchos::ArrayRCP<const double> f0_;
  RCP<Thyra::VectorBase<double>> plus_, minus_, half_;
  ColumnDifferences previous_;  ///< the longer step's differences while a shorter one is tried
  Changes standingOneSide_{}, previousOneSide_{};  ///< what changed on the side left out, of `out` and previous_
  Changes straddled_{};  ///< what changed on both sides, over the attempts at the current column
};

// The worst entry error e_ij on this rank and the sums of the norm-wise error.
struct ErrorTally {
  double worst = -1, worstW = 0, worstD = 0;
  GO worstRow = -1, worstColumn = -1;
  double sums[2] = {0, 0};  // Σ (W − D)², Σ W²

  void add(GO column, const std::vector<double>& wColumn, const ColumnDifferences& c,
           const Map& rowMap) {
    for (std::size_t r = 0; r < wColumn.size(); ++r) {
      const double w = wColumn[r], d = c.differences[r], scale = c.scales[r];
      if (w == 0 && d == 0) continue;
      const double difference = std::abs(w - d);
      double e = std::numeric_limits<double>::infinity();
      if (std::isfinite(d)) e = scale > 0 ? difference / scale : (difference > 0 ? e : 0.0);
      sums[0] += std::isfinite(d) ? difference * difference : 0.0;
      sums[1] += w * w;
      if (e > worst) {
        worst = e;
        worstRow = rowMap.getGlobalElement(static_cast<LO>(r));
        worstColumn = column;
        worstW = w;
        worstD = d;
      }
    }
  }

  // The worst entry over the ranks: the largest error, then the lowest (row, column); `last` is the
  // largest global DOF id.
  void reduceInto(JacobianComparison& result, const Teuchos::Comm<int>& comm, GO last) const {
    double global = 0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &worst, &global);
    const long long none = std::numeric_limits<long long>::max();
    const long long span = static_cast<long long>(last) + 1;
    long long key = worst == global && worstRow >= 0 ? worstRow * span + worstColumn : none, globalKey = none;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &key, &globalKey);
    double values[2] = {key == globalKey ? worstW : 0.0, key == globalKey ? worstD : 0.0}, globalValues[2];
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, values, globalValues);
    double globalSums[2];
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, sums, globalSums);
    result.worstRelativeError = std::max(global, 0.0);
    if (globalKey != none) {
      result.row = globalKey / span;
      result.column = globalKey % span;
    }
    result.assembled = globalValues[0];
    result.finiteDifference = globalValues[1];
    result.normwiseError = globalSums[1] > 0 ? std::sqrt(globalSums[0] / globalSums[1]) : std::sqrt(globalSums[0]);
  }
};

// Central differences of f, column by column (every rank walks all global columns in the same order;
// the owner of column j perturbs it), against the entries of W on this rank's rows.
JacobianComparison compareAt(const ContactMechanicsModel& model, const Thyra::VectorBase<double>& x, double lambda,
                             const Thyra::LinearOpBase<double>& W, const JacobianCheck::Options& options) {
  const auto start = std::chrono::steady_clock::now();
  auto matrix = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(Teuchos::rcpFromRef(W)), true);
  const auto& rowMap = *matrix->getRowMap();
  const auto numRows = static_cast<std::size_t>(rowMap.getNodeNumElements());
  const AssembledColumns w = assembledColumns(*matrix);
  PerturbedResiduals residuals(model, x, lambda, rowMap);
  ColumnDifferencer differencer(model, residuals, w.rowMax, options);

  JacobianComparison result;
  ErrorTally tally;
  std::vector<double> wColumn(numRows, 0.0);
  ColumnDifferences differences{std::vector<double>(numRows, 0.0), std::vector<double>(numRows, 0.0)};
  const GO first = rowMap.getMinAllGlobalIndex(), last = rowMap.getMaxAllGlobalIndex();
  for (GO j = first; j <= last; ++j) {
    const Column column = residuals.column(j, options.step);
    if (column.h == 0) continue;  // no rank has this DOF
    const auto found = w.entries.find(j);
    if (found != w.entries.end())
      for (const auto& [r, value] : found->second) wColumn[r] = value;
    if (differencer.difference(column, wColumn, result, differences))
      tally.add(j, wColumn, differences, rowMap);
    else if (result.nonSmoothColumns++ == 0)
      result.firstNonSmoothColumn = j;
    if (found != w.entries.end())
      for (const auto& [r, value] : found->second) wColumn[r] = 0.0;
  }
  tally.reduceInto(result, residuals.comm(), last);
  result.residualEvaluations = residuals.evaluations();
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Teuchos::reduceAll(residuals.comm(), Teuchos::REDUCE_MAX, 1, &seconds, &result.seconds);
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
  // The consistent tangent: Newton's W carries secant slip stiffnesses where a node's slip has just
  // reversed (SlipReversalDamping), which no difference of the residual measures (the header).
  const int secants = model.consistentJacobian(x, lambda, *W);
  auto result = compareAt(model, x, lambda, *W, options_);
  result.secantTangentNodes = secants;
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
  // How many columns a change of each part of the contact state concerned (ContactChange).
  const auto why = [](const long (&count)[3]) {
    return "status " + std::to_string(count[0]) + ", facet " + std::to_string(count[1]) + ", contact point " +
           std::to_string(count[2]);
  };
  if (r.nonSmoothColumns > 0)
    line += "; " + std::to_string(r.nonSmoothColumns) + " column(s) not compared (a contact status changes within ±h on both sides, " +
            "first: " + dof(r.firstNonSmoothColumn) + "; " + why(r.nonSmoothFor) + ")";
  if (r.oneSidedColumns > 0)
    line += "; " + std::to_string(r.oneSidedColumns) + " column(s) differenced on one side (a contact status changes on the other: " +
            why(r.oneSidedFor) + ")";
  if (r.bentColumns > 0)
    line += "; " + std::to_string(r.bentColumns) + " column(s) differenced with a shorter step (the residual bends within h)";
  if (r.secantTangentNodes > 0)
    line += "; " + std::to_string(r.secantTangentNodes) +
            " slave node(s) with a secant slip tangent in Newton's W (slip reversed; checked: the consistent one)";
  return line;
}

}  // namespace contessa::model
