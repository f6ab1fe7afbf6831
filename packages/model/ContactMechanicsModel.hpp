#pragma once
// The boundary between physics and solvers (DESIGN.md): a Thyra::ModelEvaluator over Tpetra with
// x = nodal displacements and one parameter, the load factor λ. It evaluates the residual
// f(x, λ) = f_int(x) − λ f_ext on free DOFs and x − λ ū on prescribed DOFs, the Jacobian W = ∂f/∂x
// and ∂f/∂λ. The CRS graph is built once. Continuum elements are assembled by SolidAssembler.
#include <memory>
#include <vector>

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include "deck/ProblemDefinition.hpp"
#include "mesh/Partition.hpp"
#include "model/SolidAssembler.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::model {

/// Reaction force summed over a node set: Σ (f_int − f_ext) over its nodes, the force the supports
/// exert on the body (Abaqus RF convention). Per unit thickness in 2D.
struct NodeSetReaction {
  std::string nodeSet;
  std::vector<double> force;  ///< one entry per component
};

class ContactMechanicsModel : public Thyra::StateFuncModelEvaluatorBase<double> {
 public:
  ContactMechanicsModel(const Teuchos::RCP<const Comm>& comm, const deck::ProblemDefinition& problem,
                        const mesh::Partition& partition,
                        const Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>& solverFactory);

  // Thyra::ModelEvaluator
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_p_space(int l) const override;
  Teuchos::RCP<const Teuchos::Array<std::string>> get_p_names(int l) const override;
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override;
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override;
  Teuchos::RCP<Thyra::LinearOpBase<double>> create_W_op() const override;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> get_W_factory() const override;

  // State of the increment (internal variables; contact history later).
  void commitState() { solids_->commit(); }
  void rollbackState() { solids_->rollback(); }

  // Post-processing for output, at a converged state.
  const Teuchos::RCP<const Map>& ownedDofMap() const { return ownedMap_; }
  const Teuchos::RCP<const Map>& ownedElementMap() const { return elementMap_; }
  /// Columns: σ_xx σ_yy σ_zz σ_xy [σ_yz σ_xz] von Mises, one row per owned element.
  Teuchos::RCP<MultiVector> elementStresses(const Vector& x) const;
  static std::vector<std::string> elementStressNames(int dimension);
  std::vector<NodeSetReaction> reactions(const Vector& x, double loadFactor) const;

  /// Number of Jacobian evaluations so far (each is followed by one linear solve in Newton).
  int jacobianEvaluations() const { return jacobianEvaluations_; }
  /// Load factor of the latest evaluation (the one a failed increment was trying to reach).
  double lastLoadFactor() const { return lastLoadFactor_; }
  int dimension() const { return dim_; }

 private:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override;
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& inArgs,
                     const Thyra::ModelEvaluatorBase::OutArgs<double>& outArgs) const override;

  void buildMaps(const mesh::Partition& partition);
  void buildGraph();
  void buildBoundaryConditions();
  /// Internal forces (and stiffness) at owned x, exported to owned rows, no boundary conditions.
  bool assembleInternal(const Vector& x, Vector* force, CrsMatrix* stiffness) const;

  Teuchos::RCP<const Comm> comm_;
  const deck::ProblemDefinition& problem_;
  int dim_;
  Teuchos::RCP<const Map> ownedMap_, overlapMap_, elementMap_, paramMap_;
  Teuchos::RCP<const Export> exporter_;
  Teuchos::RCP<const Import> importer_;
  Teuchos::RCP<const CrsGraph> ownedGraph_, overlapGraph_;
  Teuchos::RCP<CrsMatrix> overlapMatrix_;
  Teuchos::RCP<Vector> overlapForce_;
  mutable Teuchos::RCP<Vector> overlapX_;
  Teuchos::RCP<Vector> externalForce_;       ///< f_ext at λ = 1 (owned)
  std::vector<LO> prescribedRows_;           ///< owned local rows with a Dirichlet condition
  std::vector<double> prescribedValues_;     ///< ū at λ = 1, per prescribed row
  std::vector<char> isPrescribedOverlap_;    ///< per overlapped local DOF
  std::unique_ptr<SolidAssembler> solids_;
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> xSpace_, pSpace_;
  Thyra::ModelEvaluatorBase::InArgs<double> nominal_;
  mutable int jacobianEvaluations_ = 0;
  mutable double lastLoadFactor_ = 0;
};

}  // namespace contessa::model
