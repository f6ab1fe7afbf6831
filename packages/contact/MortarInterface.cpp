#include "contact/MortarInterface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <utility>
#include <stdexcept>
#include <type_traits>

#include "contact/BoundingBoxTree.hpp"
#include "contact/CoulombReturnMapping.hpp"
#include "contact/MasterSurface.hpp"
#include "contact/MortarFacetPair.hpp"
#include "contact/MortarQuadraticFacetPair.hpp"
#include "contact/MortarQuadraticSegment.hpp"
#include "contact/MortarSegment.hpp"
#include "contact/MortarSlipBasis.hpp"
#include "contact/SlipReversalDamping.hpp"

namespace contessa::contact {

namespace {
constexpr double kTouchingGap = 1e-10;  // as continuation::BetaOptions::touchingGap
/// The support point of a rigid master's motion (MortarInterface::addPair): no mesh node nor rigid point
/// (those are ≥ 0 and −1, −2, …).
constexpr GlobalIndex kRigidMotionPoint = std::numeric_limits<GlobalIndex>::min();

/// The largest distance between two of a facet's nodes.
template <class Facet>
double facetDiameter(const MasterFacetNodes<Facet>& m) {
  double h = 0;
  for (std::size_t a = 0; a < m.x.size(); ++a)
    for (std::size_t b = a + 1; b < m.x.size(); ++b) h = std::max(h, norm(subtract(m.x[b], m.x[a])));
  return h;
}

/// The pair kernel of the dimension: its coordinates' layout and its derivatives (MortarSegment.hpp in 2D,
/// MortarFacetPair.hpp in 3D). The rest of the interface is one code path.
template <int Dim>
struct MortarPairLayout;
template <>
struct MortarPairLayout<2> {
  static constexpr int kCoordinates = kMortarPairCoordinates;  // s0 s1 m0 m1 y0 y1 (MortarSegment.hpp)
  static constexpr int kFirstMaster = 2;
  static constexpr int kMasterNodes = 2;
  using Derivatives = MortarPairDerivatives;
  using Gaps = MortarPairGaps<double>;
  using Committed = SegmentPairCommitted;
  static constexpr int kSlipEntries = 1;  ///< the kernel's slip: along the master's tangent (eq. M9)
};
template <>
struct MortarPairLayout<3> {
  static constexpr int kCoordinates = kMortarFacetPairCoordinates;  // s0–s3 m0–m3 (MortarFacetPair.hpp)
  static constexpr int kFirstMaster = kMortarFacetNodes;
  static constexpr int kMasterNodes = kMortarFacetNodes;
  using Derivatives = MortarFacetPairDerivatives;
  using Gaps = MortarFacetPairGaps<double>;
  using Committed = FacetPairCommitted;
  static constexpr int kSlipEntries = 3;  ///< the kernel's slip: a 3-vector (eq. M9′)
};
/// 3D pairs with a quadratic face on a side (MortarQuadraticFacetPair.hpp), Slots nodes per side: 6 (a
/// Tri6: s0–s5 m0–m5), 8 (a Quad8) or 9 (a Quad9).
template <int Slots>
struct QuadraticMortarPairLayout {
  static constexpr int kCoordinates = 3 * 2 * Slots;
  static constexpr int kFirstMaster = Slots;
  static constexpr int kMasterNodes = Slots;
  using Derivatives = MortarQuadraticPairDerivatives<Slots>;
  using Gaps = MortarQuadraticFacetPairGaps<double, Slots>;
  using Committed = QuadraticFacetPairCommitted<Slots>;
  static constexpr int kSlipEntries = 3;  ///< the kernel's slip: a 3-vector (eq. M21)
};
/// 2D pairs with a 3-node segment on a side (MortarQuadraticSegment.hpp): s0–s2 m0–m2, a Line2 leaving the
/// third slot unused.
struct QuadraticSegmentPairLayout {
  static constexpr int kCoordinates = kQuadraticSegmentPairCoordinates;
  static constexpr int kFirstMaster = kQuadraticSegmentNodes;
  static constexpr int kMasterNodes = kQuadraticSegmentNodes;
  using Derivatives = MortarQuadraticSegmentDerivatives;
  using Gaps = MortarQuadraticSegmentGaps<double>;
  using Committed = QuadraticSegmentPairCommitted;
  static constexpr int kSlipEntries = 1;  ///< the kernel's slip: along the master's tangent t_m(η)
};
/// A master facet type whose interface takes the quadratic pair kernel of Slots slots (a quadratic slave
/// or master side): the same facets to MasterSurface, which reads only the type's constants.
template <class Facet, int Slots = kQuadraticFacetNodes>
struct QuadraticPairs : Facet {};
template <class Facet>
struct PairLayoutOf {
  using type = MortarPairLayout<Facet::kSpaceDim>;
};
template <class Facet, int Slots>
struct PairLayoutOf<QuadraticPairs<Facet, Slots>> {
  using type = std::conditional_t<Facet::kSpaceDim == 2, QuadraticSegmentPairLayout, QuadraticMortarPairLayout<Slots>>;
};

/// The kernels' slip increments: entry c of slave end a's (2D: the scalar along t_m; 3D: component c of
/// the 3-vector), its gradient and its Hessian.
inline double slipEntry(const MortarPairGaps<double>& g, int a, int) { return g.weightedSlip[a]; }
inline double slipEntry(const MortarFacetPairGaps<double>& g, int a, int c) { return g.weightedSlip[a][c]; }
inline double slipEntry(const MortarPairDerivatives& g, int a, int) { return g.weightedSlip[a]; }
inline double slipEntry(const MortarQuadraticSegmentGaps<double>& g, int a, int) { return g.weightedSlip[a]; }
inline double slipEntry(const MortarQuadraticSegmentDerivatives& g, int a, int) { return g.weightedSlip[a]; }
inline const double* slipGradientOf(const MortarQuadraticSegmentDerivatives& g, int a, int) { return g.slipGradient[a].data(); }
inline const double* slipVariationOf(const MortarQuadraticSegmentDerivatives& g, int a, int) { return g.slipVariation[a].data(); }
inline const double* slipVariationGradientOf(const MortarQuadraticSegmentDerivatives& g, int a, int) {
  return g.slipVariationGradient[a].data();
}
inline double slipEntry(const MortarFacetPairDerivatives& g, int a, int c) { return g.weightedSlip[a][c]; }
inline const double* slipGradientOf(const MortarPairDerivatives& g, int a, int) { return g.slipGradient[a].data(); }
inline const double* slipGradientOf(const MortarFacetPairDerivatives& g, int a, int c) { return g.slipGradient[3 * a + c].data(); }
// The virtual slips and their derivatives (MortarSlipVariation.hpp, eq. M11″): what the traction works on.
inline const double* slipVariationOf(const MortarPairDerivatives& g, int a, int) { return g.slipVariation[a].data(); }
inline const double* slipVariationOf(const MortarFacetPairDerivatives& g, int a, int c) { return g.slipVariation[3 * a + c].data(); }
inline const double* slipVariationGradientOf(const MortarPairDerivatives& g, int a, int) {
  return g.slipVariationGradient[a].data();
}
inline const double* slipVariationGradientOf(const MortarFacetPairDerivatives& g, int a, int c) {
  return g.slipVariationGradient[3 * a + c].data();
}
template <int Slots>
double slipEntry(const MortarQuadraticFacetPairGaps<double, Slots>& g, int a, int c) { return g.weightedSlip[a][c]; }
template <int Slots>
double slipEntry(const MortarQuadraticPairDerivatives<Slots>& g, int a, int c) { return g.weightedSlip[a][c]; }
template <int Slots>
const double* slipGradientOf(const MortarQuadraticPairDerivatives<Slots>& g, int a, int c) { return g.slipGradient[3 * a + c].data(); }
template <int Slots>
const double* slipVariationOf(const MortarQuadraticPairDerivatives<Slots>& g, int a, int c) {
  return g.slipVariation[3 * a + c].data();
}
template <int Slots>
const double* slipVariationGradientOf(const MortarQuadraticPairDerivatives<Slots>& g, int a, int c) {
  return g.slipVariationGradient[3 * a + c].data();
}

/// A 2D traction's restart field is its one component (the files' scalar); a 3D one's its two.
inline double& tractionField(Vector<1>& t) { return t[0]; }
inline Vector<2>& tractionField(Vector<2>& t) { return t; }

/// The weighted gap of one slave node, g̃_k = Σ over its slave segments and the master segments they meet
/// (eq. M5), with, when asked, its gradient and Hessian over its support: the nodes it depends on.
template <int kDim>
struct NodeWeightedGap {
  bool overlaps = false;  ///< some master segment meets one of the node's slave segments
  double value = 0;       ///< g̃_k
  std::vector<GlobalIndex> nodes;  ///< the support: slave node k first, then the others (rigid points < 0)
  std::vector<GlobalIndex> dofs;   ///< kDim per support node; −1 for a rigid point's
  std::vector<double> dPositiondLambda;  ///< kDim per support node: a rigid point's motion, else 0
  std::vector<double> gradient;          ///< ∂g̃_k/∂x over the support's coordinates
  std::vector<double> hessian;           ///< ∂²g̃_k/∂x², row-major
  Vector<kDim - 1> slip{};               ///< Δũ_kα in the node's tangent basis, eq. (M9), (M9′) (friction only)
  std::array<std::vector<double>, kDim - 1> slipGradient;   ///< ∂Δũ_kα/∂x (the return mapping's)
  std::array<std::vector<double>, kDim - 1> slipVariation;  ///< δũ_kα: the virtual slip (the residual's, M11″)
  std::array<std::vector<double>, kDim - 1> slipVariationGradient;  ///< ∂δũ_kα,i/∂x_j, row-major

  /// The support index of `node`, added (with its DOF ids and ∂x/∂λ) when new.
  int indexOf(GlobalIndex node, const GlobalIndex* nodeDofs, const double* motion) {
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i] == node) return static_cast<int>(i);
    nodes.push_back(node);
    for (int c = 0; c < kDim; ++c) {
      dofs.push_back(nodeDofs[c]);
      dPositiondLambda.push_back(motion[c]);
    }
    return static_cast<int>(nodes.size()) - 1;
  }
  int size() const { return kDim * static_cast<int>(nodes.size()); }
};

}  // namespace

/// The mortar interface over master facets of type MasterFacetType (2D: Line2, and QuadraticPairs of Line2 or
/// Line3 with a 3-node side; 3D: Tri3, Quad4, and QuadraticPairs of the faces with a quadratic one): see
/// MortarInterface.hpp.
template <class MasterFacetType>
class MortarInterface final : public ContactInterfaceBase {
  static constexpr int kDim = MasterFacetType::kSpaceDim;
  using Layout = typename PairLayoutOf<MasterFacetType>::type;
  using Facets = std::vector<MasterFacetNodes<MasterFacetType>>;
  using WeightedGap = NodeWeightedGap<kDim>;
  static constexpr int kSlipDim = kDim - 1;  ///< tangential components (1 in 2D, 2 in 3D)
  using Traction = Vector<kSlipDim>;
  using SlipBasis = MortarSlipBasis<kSlipDim, (Layout::kSlipEntries > 0 ? Layout::kSlipEntries : 1)>;
  /// 2D with a 3-node segment on a side: the quadratic segment kernel, on flat pieces as 3D's quadratic faces.
  static constexpr bool kQuadraticSegments = std::is_same_v<Layout, QuadraticSegmentPairLayout>;

 public:
  MortarInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave)
      : ContactInterfaceBase(std::move(spec), std::move(evaluatesSlave)),
        perFacet_(static_cast<std::size_t>(spec_.slaveNodesPerFacet())),
        master_(spec_),
        friction_(spec_.law.tangentialPenalty, spec_.law.frictionCoefficient, spec_.law.slipTolerance),
        trialTraction_(spec_.slaveNodes.size(), Traction{}),
        committedTraction_(spec_.slaveNodes.size(), Traction{}),
        normalMultiplier_(spec_.slaveNodes.size(), 0.0),
        committedNormalMultiplier_(spec_.slaveNodes.size(), 0.0),
        tangentialMultiplier_(spec_.slaveNodes.size(), Traction{}),
        iterate_(spec_.slaveNodes.size()),
        damping_(spec_.slaveNodes.size(), kRepeatedReversal) {
    const int slots = Layout::kFirstMaster;
    const bool quadratic = kDim == 3 && slots >= kQuadraticFacetNodes;
    const int nodes = static_cast<int>(perFacet_);
    const bool linearSlave = kDim == 2 ? (perFacet_ == 2 || (kQuadraticSegments && perFacet_ == 3))
                                       : (perFacet_ == 3 || perFacet_ == 4 || (quadratic && nodes >= 6 && nodes <= slots));
    // A quadratic slave face has its flat pieces' measures (deck/ProblemDefinition, MortarQuadraticFacetPair);
    // a slave segment of the quadratic segment kernel its pieces' lengths (MortarQuadraticSegment).
    const std::size_t measures = static_cast<std::size_t>(kDim == 3 ? mortarFaceMeasures(nodes)
                                                          : kQuadraticSegments ? mortarSegmentPieces(nodes) : 1);
    if (spec_.dimension != kDim || !linearSlave || spec_.slaveFacets.size() * measures != perFacet_ * spec_.slaveFacetMeasures.size())
      throw std::logic_error("MortarInterface '" + spec_.label() + "': linear slave facets with their measures expected");
    segmentsAt_.resize(spec_.slaveNodes.size());
    for (std::size_t s = 0; s < spec_.slaveFacets.size() / perFacet_; ++s)
      for (std::size_t a = 0; a < perFacet_; ++a)
        segmentsAt_[slaveIndex(spec_.slaveFacets[perFacet_ * s + a])].push_back({s, static_cast<int>(a)});
    // The slave nodes whose committed positions this rank keeps: those of an evaluated node's segments.
    keepsSlave_.assign(spec_.slaveNodes.size(), 0);
    for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k)
      if (evaluatesSlave_[k])
        for (const SegmentEnd& se : segmentsAt_[k])
          for (std::size_t a = 0; a < perFacet_; ++a) keepsSlave_[slaveIndex(spec_.slaveFacets[perFacet_ * se.segment + a])] = 1;
  }

  std::unique_ptr<ContactInterfaceBase> clone() const override { return std::make_unique<MortarInterface>(*this); }
  void setRigidMotion(const std::vector<double>& offset, const std::vector<double>& motion) override {
    master_.setMotion(offset, motion);
  }
  void setFrictionCoefficient(double mu) override {
    spec_.law.frictionCoefficient = mu;
    spec_.law.validate();
    friction_ = CoulombReturnMapping<kSlipDim>(spec_.law.tangentialPenalty, mu, spec_.law.slipTolerance);
  }
  void evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink) override;
  std::vector<SlaveNodeChange> changesAt(const NodePosition& position, double loadFactor) const override;
  /// None: a mortar node's penetration is measured by its weighted gap, which sees a master segment
  /// wherever the slave segments meet it; the swept node-through-facet test is node-to-segment's
  /// (theory-contact §12).
  std::vector<TunnellingNode> tunnellingNodes() const override { return {}; }
  void commit() override;
  void rollback() override;
  /// Augmented Lagrangian (theory-contact §13.4): the Uzawa update (eq. 15.3) of every owned slave node's
  /// multipliers on its weighted gap and weighted slip, λ_N,k ← t_N,k and λ_Tα,k ← t_Tα,k of the latest trial
  /// evaluation (0 for an open node). Plain Uzawa steps only: node-to-segment's stick secant (eq. 15.7) is
  /// not applied (`atEquilibrium` unused).
  void augment(bool atEquilibrium) override;
  void saveCommittedSlaves(StateRecord& table) const override;
  void restoreSlaves(const StateRecord& table) override;
  void saveCommittedMaster(StateRecord& table) const override;
  void restoreMaster(const StateRecord& table) override;
  void setConsistentTangents(bool consistent) override { consistentTangents_ = consistent; }
  int secantTangentNodes() const override { return secantTangentNodes_; }

 private:
  struct SegmentEnd {
    std::size_t segment;
    int end;  ///< which node of the slave facet the slave node is
  };
  std::size_t slaveIndex(GlobalIndex node) const {
    const auto& s = spec_.slaveNodes;
    const auto it = std::lower_bound(s.begin(), s.end(), node);
    if (it == s.end() || *it != node) throw std::logic_error("MortarInterface: a slave facet's node is not a slave node");
    return static_cast<std::size_t>(it - s.begin());
  }
  /// The nodes of a slave facet's pairs in the kernel's order (2D: its two slave nodes, two master nodes
  /// set per master facet, and the slave nodes beyond its ends, which enter the averaged nodal normals;
  /// 3D: its three or four slave nodes, then the master facet's).
  struct PairNodes {
    std::array<GlobalIndex, Layout::kCoordinates / kDim> nodes{};
    std::array<char, Layout::kCoordinates / kDim> used{};  ///< which entries the kernel reads
    MortarSlaveNeighbours neighbours;                     ///< 2D
    MortarFacetPairShape shape;                           ///< 3D
    double referenceMeasure = 0;
    std::size_t segment = 0;
  };
  BoundingBoxTree<kDim> searchTree(const Facets& facets) const;
  bool frictional() const { return !spec_.law.isFrictionless(); }
  WeightedGap weightedGap(std::size_t k, const NodePosition& position, const Facets& facets,
                              const BoundingBoxTree<kDim>& tree, bool derivatives) const;
  /// The committed positions of a pair's slave and master nodes (friction); false before any commit.
  bool committedPair(const PairNodes& pair, int facet, typename Layout::Committed& out) const;
  /// Slave node k's tangent basis at the slave positions `x` (MortarSlipBasis.hpp; 2D: the identity).
  SlipBasis slipBasis(std::size_t k, const std::vector<Vector<kDim>>& x) const;
  /// Coulomb's return mapping (CoulombReturnMapping, eq. 17–23) on slave node k's weighted slip increment
  /// per tributary length Δũ_k / A_k, with its pressure p_k (eq. M10, M10′).
  ReturnMappingResult<kSlipDim> tangentialTraction(std::size_t k, const WeightedGap& w, double pressure) const;
  void recordPositions(const NodePosition& position, const Facets& facets);
  PairNodes pairNodes(std::size_t segment) const;
  /// The master facet's nodes and coordinates into the pair's.
  void setMaster(PairNodes& pair, std::array<double, Layout::kCoordinates>& x, const MasterFacetNodes<MasterFacetType>& m) const;
  /// The pair's values: its overlap, its slave nodes' weighted gaps and slip increments (2D friction).
  typename Layout::Gaps pairValues(const std::array<double, Layout::kCoordinates>& x, const PairNodes& pair,
                                   int facet) const;
  /// One slave segment's pairs at the positions of the evaluation under way (`evaluation`): the
  /// segment's nodes and coordinates, the master facets the search pairs it with (sorted: the same
  /// summation order on every rank and every call) and the pairs' values. Each slave node of the
  /// segment reads them (2 in 2D, 3 or 4 in 3D), the value pass and the derivative pass alike.
  struct SegmentPairs {
    std::uint64_t evaluation = 0;
    PairNodes pair;
    std::array<double, Layout::kCoordinates> x{};  ///< the slave entries (the master's set per facet)
    std::vector<int> facets;
    std::vector<typename Layout::Gaps> values;  ///< per facet
    std::vector<std::array<double, Layout::kCoordinates>> inputs;  ///< per facet: the pair's coordinates
  };
  const SegmentPairs& segmentPairs(std::size_t segment, const NodePosition& position, const Facets& facets,
                                   const BoundingBoxTree<kDim>& tree) const;
  const typename Layout::Derivatives& pairDerivatives(const std::array<double, Layout::kCoordinates>& x,
                                                      const PairNodes& pair, int facet) const;
  void addPair(WeightedGap& w, int end, const std::array<double, Layout::kCoordinates>& x, const PairNodes& pair,
               int facet, const SlipBasis& basis) const;
  /// A pair's weighted gap's gradient and Hessian (the kernel's, row-major) into node k's (`to`: the support
  /// index of each of the kernel's coordinates, −1 where unused).
  template <class Support>
  void addGapDerivatives(WeightedGap& w, const double* gradient, const double* hessian, const Support& to) const;
  /// A pair's slip increments' derivatives into node k's components (`to`: the support index of each of
  /// the kernel's coordinates, −1 where unused).
  template <class Derivatives, class Support>
  void addSlipDerivatives(WeightedGap& w, int end, const Derivatives& g, const SlipBasis& basis, const Support& to) const;
  /// Node k's term: residual −p ∇g̃, tangent (ε/A) ∇g̃ ⊗ ∇g̃ − p ∇²g̃ (eq. M7–M8), and with friction
  /// t_T ∇Δũ and its derivative (eq. M11–M12); adds the force on the slave nodes to `force`.
  void assemble(std::size_t k, const WeightedGap& w, double pressure, const ReturnMappingResult<kSlipDim>* tangential,
                const Sink& sink, std::vector<double>& force) const;
  /// The friction's terms of node k (eq. M11–M12): t_α ∇Δũ_α and its derivative, added.
  void addTangential(std::size_t k, const WeightedGap& w, const ReturnMappingResult<kSlipDim>& tangential,
                     std::vector<double>& residual, std::vector<double>& tangent) const;
  /// Node k's state; with friction and a closed node, `tangential` receives the return mapping's result.
  SlaveNodeState stateOf(std::size_t k, const WeightedGap& w, bool frozenOpen,
                         ReturnMappingResult<kSlipDim>* tangential = nullptr) const;
  SlaveNodeChange changeOf(std::size_t k, const SlaveNodeState& trial, const ReturnMappingResult<kSlipDim>* tangential) const;
  SlaveNodeChange unchanged(std::size_t k) const {
    SlaveNodeChange c;
    c.committedGap = c.trialGap = committedOutput_[k].gap;
    c.committedStatus = c.trialStatus = committedOutput_[k].status;
    c.frictional = !spec_.law.isFrictionless();
    return c;
  }

  std::size_t perFacet_;  ///< nodes per slave facet
  MasterSurface<MasterFacetType> master_;
  std::vector<std::vector<SegmentEnd>> segmentsAt_;  ///< per slave node: its slave segments
  CoulombReturnMapping<kSlipDim> friction_;
  /// t_Tα per slave node (eq. 22): 2D along t_m, 3D in the node's basis at the last commit (slipBasis).
  std::vector<Traction> trialTraction_, committedTraction_;
  /// Augmented Lagrangian (theory-contact §13.4), per slave node: λ_N,k ≤ 0, the normal multiplier of the
  /// weighted gap in traction units (t_N,k = min(0, λ_N,k + ε_N g̃_k / A_k), eq. M22), as the evaluations use it
  /// (the increment's Uzawa updates included) and as the last commit left it (a cut-back's); and λ_Tα,k, the
  /// start of the return mapping (eq. M23): the committed traction t_Tα,n until an update within the
  /// increment (so that the penalty law, which never updates, is the return mapping from t_Tα,n as before).
  std::vector<double> normalMultiplier_, committedNormalMultiplier_;
  std::vector<Traction> tangentialMultiplier_;
  /// Per slave node, its state at the last Newton iterate as SlipReversalDamping compares it: the status, the
  /// traction t_Tα and, as the "position", the slip increment Δũ_kα / A_k (both in the node's basis, a
  /// constant of the increment); at an increment's start the committed status and traction, slip 0.
  std::vector<ContactHistory<kSlipDim>> iterate_;
  /// A node's secant starts when its slip reverses at three iterates in a row (the two-state cycle, A B A B),
  /// not at one or two (also the predictor's overshoot and Newton's correction of it on an oblique slide,
  /// which a secant would slow from the quadratic rate: verification-contact §9.5, measured).
  static constexpr int kRepeatedReversal = 3;
  SlipReversalDamping damping_;  ///< the secant tangent of nodes whose slip direction flips between iterates
  bool consistentTangents_ = false;  ///< the damping's secants left out of the tangent (setConsistentTangents)
  int secantTangentNodes_ = 0;       ///< nodes given (or, consistent, due) a secant at the last trial evaluation
  /// The iterates' comparison starts anew from the committed state (commit, rollback, restart).
  void restartIterates();
  /// With `updateTrial` (a Newton iterate): node k's state compared with the last iterate's; a node whose
  /// slip direction has just reversed takes the secant stiffness along its slip in `tangential`.
  void dampSlipReversal(std::size_t k, const WeightedGap& w, ContactStatus status,
                        ReturnMappingResult<kSlipDim>& tangential);
  std::vector<char> keepsSlave_;
  // The positions at the last evaluation and at the last commit (friction: the slip increments' start):
  // slave nodes (kept ones), and the master facets as MasterSurface gives them (a rigid one moved).
  std::vector<Vector<kDim>> trialSlave_, committedSlave_;
  Facets trialMaster_, committedMaster_;
  /// A pair's derivatives with the inputs they were computed from (its coordinates and, 2D friction, the
  /// committed positions), and the last evaluation that used them.
  struct CachedPair {
    std::array<double, Layout::kCoordinates> x{};
    typename Layout::Committed committed{};
    bool withCommitted = false;
    std::array<double, Layout::kCoordinates> motion{};  ///< a rigid master's ∂x/∂λ (its entries)
    typename Layout::Derivatives derivatives;
    std::uint64_t evaluation = 0;
  };
  /// The pairs' derivatives by (slave segment, master facet): computed once per evaluation and shared by
  /// the pair's slave nodes, and kept for the next evaluation, which reuses those whose inputs are the
  /// same to the bit (the solver evaluates the residual and then the Jacobian at the same iterate, or a
  /// pair far from the moving part of the surface): identical inputs, identical derivatives.
  mutable std::map<std::pair<std::size_t, int>, CachedPair> pairDerivatives_;
  mutable std::vector<SegmentPairs> segmentPairs_;  ///< by slave segment
  mutable std::uint64_t evaluation_ = 0;  ///< evaluations and look-aheads started (the caches' clock)
};

template <class F>
typename MortarInterface<F>::PairNodes MortarInterface<F>::pairNodes(std::size_t segment) const {
  PairNodes pair;
  pair.segment = segment;
  if ((kDim == 3 && perFacet_ >= 6) || kQuadraticSegments) {  // the pieces' measures; referenceMeasure is a linear facet's only
    const int count = static_cast<int>(perFacet_);
    const std::size_t measures = static_cast<std::size_t>(kDim == 3 ? mortarFaceMeasures(count) : mortarSegmentPieces(count));
    for (std::size_t i = 0; i < measures; ++i) pair.shape.slavePieceAreas[i] = spec_.slaveFacetMeasures[measures * segment + i];
  } else {
    pair.referenceMeasure = spec_.slaveFacetMeasures[segment];
  }
  const int slaveCount = static_cast<int>(perFacet_);
  for (int a = 0; a < slaveCount; ++a) {
    pair.nodes[a] = spec_.slaveFacets[perFacet_ * segment + a];
    pair.used[a] = 1;
  }
  if constexpr (kDim == 3 || kQuadraticSegments) {
    pair.shape.slaveNodes = slaveCount;
    pair.shape.masterNodes = F::kNodes;
  } else {
    // The neighbour segment at end a (a 2D slave surface has at most one): its other node, and whether it
    // runs into the pair's segment (σ = +1 at end 0: stored y → s_0; at end 1: s_1 → y) or against it.
    for (int a = 0; a < 2; ++a)
      for (const SegmentEnd& other : segmentsAt_[slaveIndex(pair.nodes[a])]) {
        if (other.segment == segment) continue;
        pair.nodes[4 + a] = spec_.slaveFacets[2 * other.segment + 1 - other.end];
        pair.used[4 + a] = 1;
        pair.neighbours.orientation[a] = (other.end == 1 - a) ? 1 : -1;
        break;
      }
  }
  for (int b = 0; b < F::kNodes; ++b) pair.used[Layout::kFirstMaster + b] = 1;
  return pair;
}

template <class F>
BoundingBoxTree<MortarInterface<F>::kDim> MortarInterface<F>::searchTree(const Facets& facets) const {
  // Master boxes enlarged by the largest master and slave facets: a slave facet's box then meets every
  // master facet the mortar integral can pair it with.
  double reach = 0;
  for (const auto& m : facets) reach = std::max(reach, facetDiameter(m));
  for (double h : spec_.slaveFacetLengths) reach = std::max(reach, h);
  std::vector<BoundingBox<kDim>> boxes(facets.size());
  for (std::size_t s = 0; s < facets.size(); ++s) {
    for (const auto& x : facets[s].x) boxes[s].include(x);
    boxes[s].enlarge(reach);
  }
  return BoundingBoxTree<kDim>(std::move(boxes));
}

template <class F>
void MortarInterface<F>::setMaster(PairNodes& pair, std::array<double, Layout::kCoordinates>& x,
                                   const MasterFacetNodes<F>& m) const {
  for (int b = 0; b < F::kNodes; ++b) {
    pair.nodes[Layout::kFirstMaster + b] = m.nodes[b];
    for (int c = 0; c < kDim; ++c) x[kDim * (Layout::kFirstMaster + b) + c] = m.x[b][c];
  }
}

template <class F>
auto MortarInterface<F>::pairValues(const std::array<double, Layout::kCoordinates>& x, const PairNodes& pair,
                                    int facet) const -> typename Layout::Gaps {
  typename Layout::Committed then{};
  const typename Layout::Committed* committed = frictional() && committedPair(pair, facet, then) ? &then : nullptr;
  if constexpr (kQuadraticSegments)
    return quadraticSegmentPairGaps(x, pair.shape, committed);
  else if constexpr (kDim == 2)
    return segmentPairGaps(x, pair.referenceMeasure, pair.neighbours, committed);
  else
    return facetPairGaps(x, pair.referenceMeasure, pair.shape, committed);
}

template <class F>
auto MortarInterface<F>::segmentPairs(std::size_t segment, const NodePosition& position, const Facets& facets,
                                      const BoundingBoxTree<kDim>& tree) const -> const SegmentPairs& {
  if (segmentPairs_.size() != spec_.slaveFacetMeasures.size()) segmentPairs_.resize(spec_.slaveFacetMeasures.size());
  SegmentPairs& sp = segmentPairs_[segment];
  if (sp.evaluation == evaluation_) return sp;
  sp.evaluation = evaluation_;
  sp.pair = pairNodes(segment);
  sp.x.fill(0.0);
  BoundingBox<kDim> box;
  for (int a = 0; a < Layout::kFirstMaster; ++a) {
    if (!sp.pair.used[a]) continue;
    position(sp.pair.nodes[a], &sp.x[kDim * a]);
    if (a < static_cast<int>(perFacet_)) {
      Vector<kDim> p;
      std::copy(&sp.x[kDim * a], &sp.x[kDim * a] + kDim, p.begin());
      box.include(p);
    }
  }
  for (int a = Layout::kFirstMaster + Layout::kMasterNodes; a < Layout::kCoordinates / kDim; ++a)
    if (sp.pair.used[a]) position(sp.pair.nodes[a], &sp.x[kDim * a]);
  // A pair whose coordinates are those of the last evaluation to the bit (Contact Beta's look-ahead and the
  // evaluation at the same iterate) keeps its values: identical inputs, identical values. Not with
  // friction, whose values depend on the committed positions too.
  const std::vector<int> facetsBefore = std::move(sp.facets);
  const std::vector<std::array<double, Layout::kCoordinates>> inputsBefore = std::move(sp.inputs);
  const std::vector<typename Layout::Gaps> valuesBefore = std::move(sp.values);
  sp.facets.clear();
  sp.inputs.clear();
  sp.values.clear();
  tree.queryBox(box, sp.facets);
  std::sort(sp.facets.begin(), sp.facets.end());  // the same summation order on every rank and every call
  for (int f : sp.facets) {
    PairNodes pair = sp.pair;
    std::array<double, Layout::kCoordinates> x = sp.x;
    setMaster(pair, x, facets[f]);
    const auto before = std::lower_bound(facetsBefore.begin(), facetsBefore.end(), f);
    const std::size_t i = static_cast<std::size_t>(before - facetsBefore.begin());
    const bool same = !frictional() && before != facetsBefore.end() && *before == f && inputsBefore[i] == x;
    sp.values.push_back(same ? valuesBefore[i] : pairValues(x, pair, f));
    sp.inputs.push_back(x);
  }
  return sp;
}

template <class F>
auto MortarInterface<F>::pairDerivatives(
    const std::array<double, Layout::kCoordinates>& x, const PairNodes& pair, int facet) const
    -> const typename Layout::Derivatives& {
  // Every slave node of a pair needs its derivatives: differentiated once per evaluation, and not again
  // while its inputs stay the same (pairDerivatives_).
  CachedPair& cached = pairDerivatives_[std::make_pair(pair.segment, facet)];
  typename Layout::Committed then{};
  const bool withCommitted = frictional() && committedPair(pair, facet, then);
  // A rigid master is differentiated along its motion only (MortarDual.hpp, KernelVariables).
  std::array<double, Layout::kCoordinates> motion{};
  const double* rigidMotion = nullptr;
  if (spec_.rigidMaster) {
    const auto m = master_.dPositiondLambda(facet);
    std::copy(m.begin(), m.end(), motion.begin());
    rigidMotion = motion.data();
  }
  const bool same = cached.evaluation != 0 && cached.x == x && cached.motion == motion &&
                    cached.withCommitted == withCommitted && (!withCommitted || cached.committed == then);
  cached.evaluation = evaluation_;
  if (same) return cached.derivatives;
  cached.x = x;
  cached.motion = motion;
  cached.committed = then;
  cached.withCommitted = withCommitted;
  if constexpr (kQuadraticSegments)
    cached.derivatives = quadraticSegmentPairDerivatives(x, pair.shape, withCommitted ? &then : nullptr, rigidMotion);
  else if constexpr (kDim == 2)
    cached.derivatives =
        segmentPairDerivatives(x, pair.referenceMeasure, pair.neighbours, withCommitted ? &then : nullptr, rigidMotion);
  else if constexpr (std::is_same_v<typename Layout::Derivatives, MortarFacetPairDerivatives>)
    // Filled in place: the 18 KB record (four 24 × 24 Hessians) not returned and copied.
    facetPairDerivatives(x, pair.referenceMeasure, pair.shape, rigidMotion, withCommitted ? &then : nullptr,
                         cached.derivatives);
  else
    cached.derivatives =
        facetPairDerivatives(x, pair.referenceMeasure, pair.shape, rigidMotion, withCommitted ? &then : nullptr);
  return cached.derivatives;
}

template <class F>
void MortarInterface<F>::addPair(WeightedGap& w, int end, const std::array<double, Layout::kCoordinates>& x,
                                 const PairNodes& pair, int facet, const SlipBasis& basis) const {
  const typename Layout::Derivatives& g = pairDerivatives(x, pair, facet);
  if (!g.overlaps) return;
  w.overlaps = true;
  w.value += g.weightedGap[end];
  // The slip increments' derivatives only where assemble reads them (friction), sized whenever it does and
  // summed where the kernel has them (with the committed positions: always once evaluate has recorded them).
  const bool sized = frictional() && Layout::kSlipEntries > 0;
  bool slips = false;
  if constexpr (Layout::kSlipEntries > 0) {
    slips = sized && !g.slipGradient.empty() && !g.slipVariation.empty();
    for (int a = 0; a < kSlipDim && slips; ++a)
      for (int c = 0; c < Layout::kSlipEntries; ++c) w.slip[a] += basis[a][c] * slipEntry(g, end, c);
  }
  const auto masterDofs = master_.dofs(facet);
  const auto masterMotion = master_.dPositiondLambda(facet);
  constexpr int kPairNodes = Layout::kCoordinates / kDim;
  std::array<int, kPairNodes> at{};
  for (int a = 0; a < kPairNodes; ++a) {
    if (!pair.used[a]) {
      at[a] = -1;  // no node here (no slave node beyond a 2D end, a triangle's fourth): its coordinates are unused
      continue;
    }
    const int b = a - Layout::kFirstMaster;
    const bool master = b >= 0 && b < Layout::kMasterNodes;
    GlobalIndex slaveDofs[kDim];
    for (int c = 0; c < kDim; ++c) slaveDofs[c] = kDim * pair.nodes[a] + c;
    const double still[kDim] = {};
    if (master && spec_.rigidMaster) {
      // The kernel's derivatives along the rigid motion (its first master entry; the others are zero):
      // one support point for all rigid points, no unknowns, moving as the load factor (∂x/∂λ = e_1).
      GlobalIndex none[kDim];
      double alongMotion[kDim] = {};
      std::fill(none, none + kDim, GlobalIndex{-1});
      alongMotion[0] = 1.0;
      at[a] = w.indexOf(kRigidMotionPoint, none, alongMotion);
      continue;
    }
    at[a] = master ? w.indexOf(pair.nodes[a], &masterDofs[kDim * b], &masterMotion[kDim * b])
                   : w.indexOf(pair.nodes[a], slaveDofs, still);
  }
  const int n = w.size();
  // Grow the gradients and Hessians to the support's size, keeping the entries summed so far.
  const int old = static_cast<int>(w.gradient.size());
  // In place (the rows moved to their new stride from the last, whose new place is never before its old
  // one), in storage that grows geometrically: a node's support grows pair by pair, without a new matrix
  // allocated and zeroed each time.
  const auto grow = [&](std::vector<double>& hessian) {
    hessian.resize(static_cast<std::size_t>(n) * n);
    for (int i = old - 1; i >= 0; --i) {
      for (int j = n - 1; j >= old; --j) hessian[i * n + j] = 0.0;
      for (int j = old - 1; j >= 0; --j) hessian[i * n + j] = hessian[i * old + j];
    }
    std::fill(hessian.begin() + static_cast<std::ptrdiff_t>(old) * n, hessian.end(), 0.0);
  };
  if (n != old) {
    grow(w.hessian);
    for (int a = 0; a < kSlipDim && sized; ++a) grow(w.slipVariationGradient[a]);
  }
  w.gradient.resize(static_cast<std::size_t>(n), 0.0);
  for (int a = 0; a < kSlipDim && sized; ++a) {
    w.slipGradient[a].resize(static_cast<std::size_t>(n), 0.0);
    w.slipVariation[a].resize(static_cast<std::size_t>(n), 0.0);
  }
  constexpr int m = Layout::kCoordinates;
  // Support index of each kernel coordinate (−1: unused).
  std::array<int, m> to{};
  for (int i = 0; i < m; ++i) to[i] = at[i / kDim] < 0 ? -1 : kDim * at[i / kDim] + i % kDim;
  addGapDerivatives(w, g.gradient[end].data(), g.hessian[end].data(), to);
  if constexpr (Layout::kSlipEntries > 0) {
    if (slips) addSlipDerivatives(w, end, g, basis, to);
  }
}

template <class F>
template <class Support>
void MortarInterface<F>::addGapDerivatives(WeightedGap& w, const double* gradient, const double* hessian,
                                           const Support& to) const {
  // The kernel's coordinates that carry derivatives: the used ones, of a rigid master only its first
  // entry (the derivatives along the motion; facetPairDerivatives and segmentPairDerivatives leave its
  // other entries zero). The zeros left out would add nothing (bar the signs of zero sums): a rigid
  // master's pair scatters (m/3 + 1)² entries instead of m².
  constexpr int m = Layout::kCoordinates;
  constexpr int kMotionEntry = kDim * Layout::kFirstMaster;
  std::array<int, m> carried{};
  int count = 0;
  for (int i = 0; i < m; ++i) {
    const bool rigidZero = spec_.rigidMaster && i > kMotionEntry && i < kDim * (Layout::kFirstMaster + Layout::kMasterNodes);
    if (to[i] >= 0 && !rigidZero) carried[count++] = i;
  }
  const int n = w.size();
  for (int a = 0; a < count; ++a) {
    const int i = carried[a];
    w.gradient[to[i]] += gradient[i];
    double* row = &w.hessian[static_cast<std::size_t>(to[i]) * n];
    for (int b = 0; b < count; ++b) row[to[carried[b]]] += hessian[i * m + carried[b]];
  }
}

template <class F>
template <class Derivatives, class Support>
void MortarInterface<F>::addSlipDerivatives(WeightedGap& w, int end, const Derivatives& g, const SlipBasis& basis,
                                            const Support& to) const {
  // Δũ_kα = e_α · Δũ_k: the basis is a constant of the increment (MortarSlipBasis.hpp), so the components'
  // derivatives are the basis' combinations of the kernel's.
  constexpr int m = Layout::kCoordinates;
  const int n = w.size();
  for (int c = 0; c < Layout::kSlipEntries; ++c) {
    const double* gradient = slipGradientOf(g, end, c);
    const double* variation = slipVariationOf(g, end, c);
    const double* variationGradient = slipVariationGradientOf(g, end, c);
    for (int a = 0; a < kSlipDim; ++a) {
      const double e = basis[a][c];
      if (e == 0.0) continue;
      for (int i = 0; i < m; ++i) {
        if (to[i] < 0) continue;
        w.slipGradient[a][to[i]] += e * gradient[i];
        w.slipVariation[a][to[i]] += e * variation[i];
        for (int j = 0; j < m; ++j)
          if (to[j] >= 0) w.slipVariationGradient[a][to[i] * n + to[j]] += e * variationGradient[i * m + j];
      }
    }
  }
}

template <class F>
bool MortarInterface<F>::committedPair(const PairNodes& pair, int facet, typename Layout::Committed& out) const {
  if (committedSlave_.empty() || static_cast<std::size_t>(facet) >= committedMaster_.size()) return false;
  if constexpr (kDim == 3 || kQuadraticSegments) {
    // FacetPairCoordinates' layout (QuadraticFacetPairCoordinates' on quadratic faces, and
    // QuadraticSegmentPairCoordinates'): the slave facet's nodes, then the master facet's from slot kFirstMaster.
    out.fill(0.0);
    for (std::size_t a = 0; a < perFacet_; ++a) {
      const Vector<kDim>& xs = committedSlave_[slaveIndex(pair.nodes[a])];
      std::copy(xs.begin(), xs.end(), &out[kDim * a]);
    }
    const auto& master = committedMaster_[facet].x;
    for (std::size_t b = 0; b < master.size(); ++b)
      std::copy(master[b].begin(), master[b].end(), &out[kDim * (Layout::kFirstMaster + b)]);
    return true;
  } else {
    for (int a = 0; a < 2; ++a) {
      const Vector<kDim>& xs = committedSlave_[slaveIndex(pair.nodes[a])];
      const Vector<kDim>& xm = committedMaster_[facet].x[a];
      for (int c = 0; c < kDim; ++c) {
        out[kDim * a + c] = xs[c];
        out[4 + kDim * a + c] = xm[c];
      }
    }
    return true;
  }
}

template <class F>
void MortarInterface<F>::recordPositions(const NodePosition& position, const Facets& facets) {
  trialSlave_.resize(spec_.slaveNodes.size());
  for (std::size_t j = 0; j < spec_.slaveNodes.size(); ++j)
    if (keepsSlave_[j]) position(spec_.slaveNodes[j], trialSlave_[j].data());
  trialMaster_ = facets;
  // Before the first commit the reference is the first state evaluated (the initial one).
  if (committedSlave_.empty()) committedSlave_ = trialSlave_;
  if (committedMaster_.empty()) committedMaster_ = trialMaster_;
}

template <class F>
auto MortarInterface<F>::tangentialTraction(std::size_t k, const WeightedGap& w, double pressure) const
    -> ReturnMappingResult<kSlipDim> {
  ReturnMappingInput<kSlipDim> in;
  // λ_Tα,k (eq. M23): t_Tα,n with the penalty law and before the increment's first update.
  in.committedTraction = tangentialMultiplier_[k];
  for (int a = 0; a < kSlipDim; ++a) {
    in.slipIncrement[a] = w.slip[a] / spec_.slaveAreas[k];  // a length: Δũ_k is a slip times an area
    in.metric(a, a) = 1.0;  // components along orthonormal tangents (2D t_m; 3D the node's basis)
  }
  in.normalTraction = -pressure;
  in.facetLength = spec_.slaveFacetLengths[k];
  // As node-to-segment (NodeToFacetContact): with the augmented Lagrangian the slip tolerance's ε_T follows
  // λ_N,k, a constant between two updates, not t_N (theory-contact §15, "The stick penalty").
  if (spec_.law.isAugmented()) in.frozenNormalTraction = normalMultiplier_[k];
  return friction_.map(in);
}

template <class F>
auto MortarInterface<F>::slipBasis(std::size_t k, const std::vector<Vector<kDim>>& x) const -> SlipBasis {
  SlipBasis basis{};
  if constexpr (kDim == 2) {
    basis[0][0] = 1.0;  // 2D: the kernel's slip is the component along t_m already
  } else {
    if (x.empty()) return basis;  // no positions yet: no slip increments either
    // n_k: the normalised sum of the unit normals of node k's slave facets (MortarSlipBasis.hpp), a
    // quadratic face's from its corners (a Tri6's first three nodes, a Quad8's or Quad9's first four).
    const std::size_t cornerCount = perFacet_ == 6 ? 3 : std::min<std::size_t>(perFacet_, 4);
    Vector<3> normal{};
    for (const SegmentEnd& se : segmentsAt_[k]) {
      std::vector<Vector<3>> corners;
      for (std::size_t a = 0; a < cornerCount; ++a) corners.push_back(x[slaveIndex(spec_.slaveFacets[perFacet_ * se.segment + a])]);
      normal = add(normal, linearFacetNormal(corners));
    }
    const double length = norm(normal);
    if (!(length > 0.0)) return basis;
    basis = tangentBasis(scaled(1.0 / length, normal));
  }
  return basis;
}

template <class F>
auto MortarInterface<F>::weightedGap(std::size_t k, const NodePosition& position, const Facets& facets,
                                     const BoundingBoxTree<kDim>& tree, bool derivatives) const -> WeightedGap {
  WeightedGap w;
  const SlipBasis basis = frictional() ? slipBasis(k, committedSlave_) : SlipBasis{};
  if (derivatives) {  // slave node k first: the assembly reads the slave node from the first DOFs
    const GlobalIndex node = spec_.slaveNodes[k];
    GlobalIndex dofs[kDim];
    for (int c = 0; c < kDim; ++c) dofs[c] = kDim * node + c;
    const double still[kDim] = {};
    w.indexOf(node, dofs, still);
    w.gradient.assign(kDim, 0.0);
    w.hessian.assign(kDim * kDim, 0.0);
    for (int a = 0; a < kSlipDim; ++a) {
      w.slipGradient[a].assign(kDim, 0.0);
      w.slipVariation[a].assign(kDim, 0.0);
      w.slipVariationGradient[a].assign(kDim * kDim, 0.0);
    }
  }
  for (const SegmentEnd& se : segmentsAt_[k]) {
    const SegmentPairs& sp = segmentPairs(se.segment, position, facets, tree);
    for (std::size_t i = 0; i < sp.facets.size(); ++i) {
      if (!derivatives) {
        const typename Layout::Gaps& g = sp.values[i];
        w.overlaps = w.overlaps || g.overlaps;
        if (!g.overlaps) continue;
        w.value += g.weightedGap[se.end];
        if constexpr (Layout::kSlipEntries > 0)
          for (int a = 0; a < kSlipDim; ++a)
            for (int c = 0; c < Layout::kSlipEntries; ++c) w.slip[a] += basis[a][c] * slipEntry(g, se.end, c);
        continue;
      }
      PairNodes pair = sp.pair;
      std::array<double, Layout::kCoordinates> x = sp.x;
      setMaster(pair, x, facets[sp.facets[i]]);
      addPair(w, se.end, x, pair, sp.facets[i], basis);
    }
  }
  return w;
}
template <class F>
SlaveNodeState MortarInterface<F>::stateOf(std::size_t k, const WeightedGap& w, bool frozenOpen,
                                        ReturnMappingResult<kSlipDim>* tangential) const {
  SlaveNodeState out;
  // The gap shown and counted: g̃_k / A_k, so that the pressure is −ε_N times it, as t_N = ε_N g_N (eq. 16).
  out.gap = w.overlaps ? w.value / spec_.slaveAreas[k] : std::numeric_limits<double>::infinity();
  out.slip = committedOutput_[k].slip;
  // t_N,k = min(0, λ_N,k + ε_N g̃_k / A_k) (eq. M22; λ_N,k = 0 with the penalty law: eq. M6): a node held by
  // λ_N,k < 0 is closed while g̃_k / A_k < −λ_N,k / ε_N, possibly at a small positive weighted gap.
  const double multiplier = normalMultiplier_[k];
  const double normalTraction = multiplier + spec_.law.normalPenalty * out.gap;
  if (w.overlaps && normalTraction < 0.0 && !frozenOpen) {
    out.status = ContactStatus::Slip;  // frictionless: free sliding, as node-to-segment reports it
    out.pressure = -normalTraction;
    if (frictional()) {
      const ReturnMappingResult<kSlipDim> t = tangentialTraction(k, w, out.pressure);
      out.status = t.status;
      out.slip += norm(w.slip) / spec_.slaveAreas[k];
      // The stick spring's stretch: ‖t_T‖/ε_T with the penalty law; with the augmented Lagrangian ‖t_T − λ_T‖/ε_T
      // of a sticking node, its weighted motion over the increment (eq. M23), the quantity the Elastic Slip
      // Tolerance bounds (node-to-segment's elasticSlipOf).
      if (!spec_.law.isAugmented())
        out.elasticSlip = t.tangentialPenalty > 0.0 ? norm(t.traction) / t.tangentialPenalty : 0.0;
      else if (t.status == ContactStatus::Stick && t.tangentialPenalty > 0.0)
        out.elasticSlip = norm(subtract(t.traction, tangentialMultiplier_[k])) / t.tangentialPenalty;
      if (tangential != nullptr) *tangential = t;
    }
  }
  return out;
}

template <class F>
SlaveNodeChange MortarInterface<F>::changeOf(std::size_t k, const SlaveNodeState& trial,
                                          const ReturnMappingResult<kSlipDim>* tangential) const {
  SlaveNodeChange c = unchanged(k);
  c.trialGap = trial.gap;
  c.trialStatus = trial.status;
  c.trialFacet = trial.status == ContactStatus::Open ? -1 : 0;
  if (tangential == nullptr || committedOutput_[k].status == ContactStatus::Open) return c;
  // Coulomb indicators (eq. 19, 21) in the node's tangent components: the committed traction is "driven
  // the other way" when it points against the trial traction (2D: the opposite sign).
  const double mu = spec_.law.frictionCoefficient;
  const bool opposite = dot(committedTraction_[k], tangential->trialTraction) < 0.0;
  const double committedNorm = norm(committedTraction_[k]);
  c.committedIndicator = (opposite ? -committedNorm : committedNorm) - mu * committedOutput_[k].pressure;
  c.trialIndicator = tangential->trialIndicator;
  c.slipReversed = opposite && committedOutput_[k].status == ContactStatus::Slip && trial.status == ContactStatus::Slip;
  return c;
}

template <class F>
void MortarInterface<F>::addTangential(std::size_t k, const WeightedGap& w, const ReturnMappingResult<kSlipDim>& tangential,
                                       std::vector<double>& residual, std::vector<double>& tangent) const {
  // eq. M11″–M12″: r_T = t_α δũ_kα, the traction's work on the virtual slip (the D and M matrices at the
  // current segmentation, not ∇Δũ_kα, which adds the overlap's change times the increment's slip:
  // MortarSlipVariation.hpp); t_α depends on Δũ_kβ / A_k (through ∇Δũ) and on t_N = ε_N g̃_k / A_k.
  const int n = w.size();
  const double area = spec_.slaveAreas[k];
  const double stiffness = spec_.law.normalPenalty / area;
  std::vector<double> dTraction(static_cast<std::size_t>(n));  // ∂t_α/∂x
  for (int a = 0; a < kSlipDim; ++a) {
    const double t = tangential.traction[a];
    const double dNormal = tangential.dTraction_dNormalTraction[a] * stiffness;
    const std::vector<double>& ga = w.slipVariation[a];
    for (int j = 0; j < n; ++j) {
      double d = tangential.dTraction_dSlipIncrement(a, 0) / area * w.slipGradient[0][j];
      for (int b = 1; b < kSlipDim; ++b) d += tangential.dTraction_dSlipIncrement(a, b) / area * w.slipGradient[b][j];
      dTraction[j] = d + dNormal * w.gradient[j];
    }
    for (int i = 0; i < n; ++i) {
      residual[i] += t * ga[i];
      for (int j = 0; j < n; ++j) tangent[i * n + j] += ga[i] * dTraction[j] + t * w.slipVariationGradient[a][i * n + j];
    }
  }
}

template <class F>
void MortarInterface<F>::assemble(std::size_t k, const WeightedGap& w, double pressure,
                               const ReturnMappingResult<kSlipDim>* tangential, const Sink& sink,
                               std::vector<double>& force) const {
  const int n = w.size();
  const double area = spec_.slaveAreas[k];
  const double stiffness = spec_.law.normalPenalty / area;
  std::vector<double> residual(static_cast<std::size_t>(n)), tangent(static_cast<std::size_t>(n) * n),
      dLambda(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    residual[i] = -pressure * w.gradient[i];
    for (int j = 0; j < n; ++j)
      tangent[i * n + j] = stiffness * w.gradient[i] * w.gradient[j] - pressure * w.hessian[i * n + j];
  }
  if (tangential != nullptr) addTangential(k, w, *tangential, residual, tangent);
  // A rigid master moves as X + λ · motion: ∂r/∂λ = K[:, rigid] · motion.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) dLambda[i] += tangent[i * n + j] * w.dPositiondLambda[j];
  sink(w.dofs.data(), n, residual.data(), tangent.data(), dLambda.data());
  const auto& slaves = spec_.slaveNodes;
  for (std::size_t a = 0; a < w.nodes.size(); ++a)
    if (std::binary_search(slaves.begin(), slaves.end(), w.nodes[a]))
      for (int c = 0; c < kDim; ++c) force[c] -= residual[kDim * a + c];
}

template <class F>
void MortarInterface<F>::evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink) {
  const Facets facets = master_.facets(position, loadFactor);
  const BoundingBoxTree<kDim> tree = searchTree(facets);
  if (frictional()) recordPositions(position, facets);
  ++evaluation_;
  std::vector<double> force(kDim, 0.0);
  if (updateTrial) secantTangentNodes_ = 0;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    // Frozen: nodes open at the commit carry no force, except those already touching (zero gap).
    const bool frozenOpen = frozen_ && committedOutput_[k].status == ContactStatus::Open &&
                            !(committedOutput_[k].gap <= kTouchingGap);
    WeightedGap w = weightedGap(k, position, facets, tree, false);
    ReturnMappingResult<kSlipDim> tangential;
    SlaveNodeState out = stateOf(k, w, frozenOpen, &tangential);
    const bool closed = out.status != ContactStatus::Open;
    if (closed) {
      w = weightedGap(k, position, facets, tree, true);
      if (frictional()) out = stateOf(k, w, frozenOpen, &tangential);  // the same values, summed in one order
      if (frictional() && updateTrial) dampSlipReversal(k, w, out.status, tangential);
      assemble(k, w, out.pressure, frictional() ? &tangential : nullptr, sink, force);
    }
    if (updateTrial && frictional() && !closed) dampSlipReversal(k, w, out.status, tangential);
    if (updateTrial) {
      trialOutput_[k] = out;
      trialTraction_[k] = closed && frictional() ? tangential.traction : Traction{};
      trialChanges_[k] = changeOf(k, out, closed && frictional() ? &tangential : nullptr);
    }
  }
  if (updateTrial) trialForce_ = force;
  // Pairs this evaluation did not use (opened, or out of reach) are dropped.
  for (auto it = pairDerivatives_.begin(); it != pairDerivatives_.end();)
    it = it->second.evaluation == evaluation_ ? std::next(it) : pairDerivatives_.erase(it);
}

template <class F>
std::vector<SlaveNodeChange> MortarInterface<F>::changesAt(const NodePosition& position, double loadFactor) const {
  const Facets facets = master_.facets(position, loadFactor);
  const BoundingBoxTree<kDim> tree = searchTree(facets);
  ++evaluation_;  // other positions: the segments' pairs anew
  std::vector<SlaveNodeChange> out;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    ReturnMappingResult<kSlipDim> tangential;
    const SlaveNodeState state = stateOf(k, weightedGap(k, position, facets, tree, false), false, &tangential);
    const bool frictionalClosed = frictional() && state.status != ContactStatus::Open;
    out.push_back(changeOf(k, state, frictionalClosed ? &tangential : nullptr));
  }
  return out;
}

template <class F>
void MortarInterface<F>::commit() {
  ContactCounts counts;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k] || trialOutput_[k].status == ContactStatus::Open) continue;
    ++counts.active;
    if (committedOutput_[k].status == ContactStatus::Open) ++counts.newlyActive;
    // Without friction a closed node is neither sticking nor slipping (stateOf marks it Slip only because
    // it slides freely): it counts as active alone, stick = slip = 0, as node-to-facet (issue 25, point 4).
    if (!frictional()) continue;
    if (trialOutput_[k].status == ContactStatus::Stick) ++counts.stick;
    if (trialOutput_[k].status == ContactStatus::Slip) ++counts.slip;
  }
  committedIncrement_ = trialChanges_;
  committedOutput_ = trialOutput_;
  committedForce_ = trialForce_;
  committedCounts_ = counts;
  committedTraction_ = trialTraction_;
  // 3D: the tractions into the nodes' bases at the new committed positions (MortarSlipBasis.hpp).
  if constexpr (kDim == 3 && Layout::kSlipEntries > 0) {
    if (frictional() && !trialSlave_.empty() && !committedSlave_.empty())
      for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k)
        if (evaluatesSlave_[k])
          committedTraction_[k] = transportTraction(committedTraction_[k], slipBasis(k, committedSlave_), slipBasis(k, trialSlave_));
    // The trial traction too: until the next evaluation the trial state is the committed one, and a second
    // commit without an evaluation between (the continuation commits its initial state twice) must find it
    // in the new basis, not carry the old basis' components into it (issue 25, verification §9.4).
    trialTraction_ = committedTraction_;
  }
  // The multipliers carried so that the converged state stays an equilibrium (theory-contact §15, "State"):
  // λ_N,k the one the increment used (t_N,k = λ_N,k + ε_N g̃_k / A_k unchanged), 0 for a node that opened;
  // λ_Tα,k the converged traction, the slip increments' start moving to the new committed positions (where
  // the trial of eq. M23 is λ_Tα,k: the same traction).
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k)
    if (evaluatesSlave_[k] && trialOutput_[k].status == ContactStatus::Open) normalMultiplier_[k] = 0.0;
  committedNormalMultiplier_ = normalMultiplier_;
  tangentialMultiplier_ = committedTraction_;
  if (!trialSlave_.empty()) committedSlave_ = trialSlave_;
  if (!trialMaster_.empty()) committedMaster_ = trialMaster_;
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
  restartIterates();
}

template <class F>
void MortarInterface<F>::rollback() {
  trialOutput_ = committedOutput_;
  trialForce_ = committedForce_;
  trialTraction_ = committedTraction_;
  trialSlave_ = committedSlave_;
  trialMaster_ = committedMaster_;
  // The increment's multiplier updates are forgotten with the rest of it.
  normalMultiplier_ = committedNormalMultiplier_;
  tangentialMultiplier_ = committedTraction_;
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
  restartIterates();
}

template <class F>
void MortarInterface<F>::augment(bool /*atEquilibrium*/) {
  // eq. 15.3 on the weighted quantities: the tractions of the latest trial evaluation (its pressure and its
  // return-mapped t_Tα,k; an open node has none, trialTraction_ 0). The rest of the state (the slip
  // increments' start at the committed positions, the committed traction) stays: a sticking node's weighted
  // motion over the increment then shrinks by K/(K + ε_T) per update (§15).
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const bool closed = trialOutput_[k].status != ContactStatus::Open;
    normalMultiplier_[k] = closed ? -trialOutput_[k].pressure : 0.0;
    tangentialMultiplier_[k] = closed ? trialTraction_[k] : Traction{};
  }
}

namespace {
// A mortar slave node's fields in the restart file: its change over the last increment, its output, its
// tangential traction and its committed position (NaN when no friction kept it: the slip increments'
// start, eq. M9).
// The normal multiplier λ_N,k of the augmented Lagrangian (0 with the penalty law); its tangential one is
// the tangential traction at a commit.
template <class Change, class Output, class Traction, class Position, class Fields>
void mortarSlaveFields(Change& c, Output& o, Traction& traction, double& normalMultiplier, Position& position,
                       Fields& field) {
  slaveChangeFields(c, field);
  slaveOutputFields(o, field);
  field("tangential_traction", traction);
  field("normal_multiplier", normalMultiplier);
  field("position", position, StateValues::AnyDouble);
}
}  // namespace

template <class F>
void MortarInterface<F>::saveCommittedSlaves(StateRecord& table) const {
  StateTableWriter rows(table);
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave()[k]) continue;
    rows.beginRow(static_cast<std::int64_t>(k));
    SlaveNodeChange c = committedIncrement_[k];
    SlaveNodeState o = committedOutput_[k];
    Traction traction = committedTraction_[k];
    Vector<kDim> x;
    x.fill(std::numeric_limits<double>::quiet_NaN());
    if (!committedSlave_.empty()) x = committedSlave_[k];
    double normal = committedNormalMultiplier_[k];
    mortarSlaveFields(c, o, tractionField(traction), normal, x, rows);
  }
  rows.finish();
}

template <class F>
void MortarInterface<F>::restoreSlaves(const StateRecord& table) {
  StateTableReader rows(table);
  std::vector<Vector<kDim>> positions(spec_.slaveNodes.size());
  std::vector<char> known(spec_.slaveNodes.size(), 0);
  readSlaveRows(table, rows, [&](std::size_t k) {
    SlaveNodeChange c;
    SlaveNodeState o;
    Traction traction{};
    Vector<kDim> x{};
    double normal = 0.0;
    mortarSlaveFields(c, o, tractionField(traction), normal, x, rows);
    // Every row's position: a node's neighbour may be owned by another rank.
    known[k] = std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
    positions[k] = x;
    if (!evaluatesSlave()[k]) return;
    committedIncrement_[k] = c;
    committedOutput_[k] = trialOutput_[k] = o;
    committedTraction_[k] = trialTraction_[k] = tangentialMultiplier_[k] = traction;
    committedNormalMultiplier_[k] = normalMultiplier_[k] = normal;
    trialChanges_[k] = unchanged(k);
  });
  // Without every kept node's position (a frictionless run's file) the first evaluation is the reference.
  bool complete = true;
  for (std::size_t j = 0; j < known.size(); ++j) complete = complete && (known[j] || !keepsSlave_[j]);
  if (complete) committedSlave_ = trialSlave_ = positions;
  restartIterates();
}

template <class F>
void MortarInterface<F>::restartIterates() {
  damping_.reset();
  for (std::size_t k = 0; k < iterate_.size(); ++k) {
    iterate_[k] = ContactHistory<kSlipDim>{};
    iterate_[k].status = committedOutput_[k].status;
    iterate_[k].tangentialTraction = committedTraction_[k];
  }
}

template <class F>
void MortarInterface<F>::dampSlipReversal(std::size_t k, const WeightedGap& w, ContactStatus status,
                                          ReturnMappingResult<kSlipDim>& tangential) {
  // A slipping node has no stiffness along its slip (eq. 27): where nothing else holds the master along it
  // (a body held by soft springs and the contact), Newton's step carries every node across its stick range
  // into slip the other way and the next one back, a two-state cycle (docs/verification-contact.md §9.5).
  // As node-to-segment (SlipReversalDamping), but only once a node reverses at three iterates in a row (one
  // or two are also an overshoot on an oblique slide and its correction, which the secant would slow from
  // Newton's quadratic rate to regula falsi's, §9.5): the secant of the traction between the two iterates
  // along the slip, at most the stick stiffness ε_T (metric 1 in the node's basis), regula falsi on the
  // node's friction law. The residual is untouched, so is the converged answer; with consistent tangents (the Jacobian
  // check) the node is counted and its tangent left consistent.
  ContactHistory<kSlipDim> now;
  now.segment = 0;
  now.status = status;
  if (status != ContactStatus::Open) {
    now.tangentialTraction = tangential.traction;
    for (int a = 0; a < kSlipDim; ++a) now.xi[a] = w.slip[a] / spec_.slaveAreas[k];
  }
  damping_.observe(k, iterate_[k], now);
  iterate_[k] = now;
  const SlipTangent secant = damping_.tangent(k);
  if (!secant.secant || status != ContactStatus::Slip || !(norm(tangential.trialDirection) > 0.0)) return;
  ++secantTangentNodes_;
  if (consistentTangents_) return;
  const Vector<kSlipDim> s = scaled(1.0 / norm(tangential.trialDirection), tangential.trialDirection);
  Matrix<kSlipDim, kSlipDim>& dT = tangential.dTraction_dSlipIncrement;
  const double along = dot(s, multiply(dT, s));
  const double stiffness = std::min(secant.stiffness, tangential.tangentialPenalty) - along;
  for (int a = 0; a < kSlipDim; ++a)
    for (int b = 0; b < kSlipDim; ++b) dT(a, b) += stiffness * s[a] * s[b];
}

namespace {
template <class Facet, class Fields>
void mortarMasterFields(Facet& m, Fields& field) {
  field("facet", m.id);
  field("nodes", m.nodes);
  field("x", m.x);
}
}  // namespace

template <class F>
void MortarInterface<F>::saveCommittedMaster(StateRecord& table) const {
  StateTableWriter rows(table);
  for (std::size_t i = 0; i < committedMaster_.size(); ++i) {
    rows.beginRow(static_cast<std::int64_t>(i));
    auto m = committedMaster_[i];
    mortarMasterFields(m, rows);
  }
  rows.finish();
}

template <class F>
void MortarInterface<F>::restoreMaster(const StateRecord& table) {
  StateTableReader rows(table);
  Facets facets(rows.rows());
  for (std::size_t i = 0; i < facets.size(); ++i) {
    rows.seek(static_cast<std::int64_t>(i), "master segment " + std::to_string(i));
    mortarMasterFields(facets[i], rows);
  }
  committedMaster_ = trialMaster_ = std::move(facets);
}

namespace {
/// The interface of a pair layout of Slots slots, by the master's facet type.
template <int Slots>
std::unique_ptr<ContactInterfaceBase> makeQuadraticMortarInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave) {
  const int master = spec.nodesPerFacet();
  if (master == 3) return std::make_unique<MortarInterface<QuadraticPairs<Tri3Facet, Slots>>>(std::move(spec), std::move(evaluatesSlave));
  if (master == 4) return std::make_unique<MortarInterface<QuadraticPairs<Quad4Facet, Slots>>>(std::move(spec), std::move(evaluatesSlave));
  if (master == 6) return std::make_unique<MortarInterface<QuadraticPairs<Tri6Facet, Slots>>>(std::move(spec), std::move(evaluatesSlave));
  if constexpr (Slots >= 8)
    if (master == 8) return std::make_unique<MortarInterface<QuadraticPairs<Quad8Facet, Slots>>>(std::move(spec), std::move(evaluatesSlave));
  if constexpr (Slots >= 9)
    if (master == 9) return std::make_unique<MortarInterface<QuadraticPairs<Quad9Facet, Slots>>>(std::move(spec), std::move(evaluatesSlave));
  throw std::logic_error("MortarInterface '" + spec.label() + "': master facets of 3, 4, 6, 8 or 9 nodes expected");
}
}  // namespace

std::unique_ptr<ContactInterfaceBase> makeMortarInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave) {
  if (spec.dimension == 2) {
    // A 3-node segment on either side: the quadratic segment kernel (MortarQuadraticSegment.hpp).
    if (spec.slaveNodesPerFacet() == 3 && spec.nodesPerFacet() == 2)
      return std::make_unique<MortarInterface<QuadraticPairs<Line2Facet, 3>>>(std::move(spec), std::move(evaluatesSlave));
    if (spec.nodesPerFacet() == 3)
      return std::make_unique<MortarInterface<QuadraticPairs<Line3Facet, 3>>>(std::move(spec), std::move(evaluatesSlave));
    return std::make_unique<MortarInterface<Line2Facet>>(std::move(spec), std::move(evaluatesSlave));
  }
  const int slots = quadraticPairSlots(spec.slaveNodesPerFacet(), spec.nodesPerFacet());
  if (slots == 9) return makeQuadraticMortarInterface<9>(std::move(spec), std::move(evaluatesSlave));
  if (slots == 8) return makeQuadraticMortarInterface<8>(std::move(spec), std::move(evaluatesSlave));
  if (slots == 6) return makeQuadraticMortarInterface<6>(std::move(spec), std::move(evaluatesSlave));
  if (spec.nodesPerFacet() == 3) return std::make_unique<MortarInterface<Tri3Facet>>(std::move(spec), std::move(evaluatesSlave));
  return std::make_unique<MortarInterface<Quad4Facet>>(std::move(spec), std::move(evaluatesSlave));
}

ContactInterfaceSpec mortarReservationSpec(const ContactInterfaceSpec& spec) {
  ContactInterfaceSpec out = spec;
  double slaveSize = 0;
  for (double h : spec.slaveFacetLengths) slaveSize = std::max(slaveSize, h);
  // The run-time search pairs a slave segment with master segments up to a master and a slave segment
  // length away (searchTree); the node is one slave segment from the far end of its segments.
  out.searchReach = std::max(0.0, spec.searchReach) + 2.0 * slaveSize;
  return out;
}

std::vector<std::size_t> mortarSlaveNeighbours(const ContactInterfaceSpec& spec, std::size_t k) {
  const auto& s = spec.slaveNodes;
  const auto index = [&](GlobalIndex node) { return static_cast<std::size_t>(std::lower_bound(s.begin(), s.end(), node) - s.begin()); };
  const std::size_t perFacet = static_cast<std::size_t>(spec.slaveNodesPerFacet());
  // The other nodes of the slave facets at node j.
  const auto adjacent = [&](std::size_t j, std::vector<std::size_t>& out) {
    for (std::size_t f = 0; f + perFacet <= spec.slaveFacets.size(); f += perFacet)
      if (std::find(&spec.slaveFacets[f], &spec.slaveFacets[f] + perFacet, s[j]) != &spec.slaveFacets[f] + perFacet)
        for (std::size_t a = 0; a < perFacet; ++a)
          if (spec.slaveFacets[f + a] != s[j]) out.push_back(index(spec.slaveFacets[f + a]));
  };
  std::vector<std::size_t> near{k};
  adjacent(k, near);
  std::vector<std::size_t> out = near;
  // 2D: two segments away, the nodal normals at node k's neighbours depending on their own neighbours.
  // 3D: one facet away, a facet pair depending on its own nodes only (MortarFacetPair.hpp).
  if (spec.dimension == 2)
    for (std::size_t i = 1; i < near.size(); ++i) adjacent(near[i], out);
  std::sort(out.begin() + 1, out.end());
  out.erase(std::unique(out.begin() + 1, out.end()), out.end());
  out.erase(std::remove(out.begin() + 1, out.end(), k), out.end());
  return out;
}

}  // namespace contessa::contact
