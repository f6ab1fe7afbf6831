#pragma once
// What a solver needs to say why a Newton solve failed or must not be accepted, and to count its work,
// without knowing what an element or a contact pair is (docs/design.md): the model answers in words.
// Every call is collective: every rank calls it at the same point and gets the same text.
// No Trilinos, no element or contact types.
#include <string>
#include <vector>

namespace contessa::model {

class SolveDiagnostics {
 public:
  virtual ~SolveDiagnostics() = default;
  /// Why the residual of the latest evaluation is not finite (NaN or infinite), e.g. "element 17 of block
  /// 'tube' is inverted or degenerate (det F <= 0)"; empty when the model knows no reason.
  virtual std::string nonFiniteResidualCause() const = 0;
  /// Why the latest evaluated state is no answer although the residual converged (a body passed through
  /// another since the last commit), e.g. "slave node 41 of interface 'plate' (and 28 more) passed through
  /// the master surface"; empty when it is acceptable.
  virtual std::string contactTunnelling() const = 0;
  /// The null space of a singular Jacobian (vectors over all DOFs in global numbering, the same on every
  /// rank) in words: what is free to move, and how.
  virtual std::string describeFreeMotion(const std::vector<std::vector<double>>& nullSpace) const = 0;
  /// Whether bodies may hold each other by contact (the advice for a singular stiffness depends on it).
  virtual bool hasContact() const = 0;
  /// Jacobian evaluations so far (each is followed by one linear solve in Newton).
  virtual int jacobianEvaluations() const = 0;
};

}  // namespace contessa::model
