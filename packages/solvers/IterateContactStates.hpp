#pragma once
// With Newton Details on, one line per Newton iterate with the contact states the model evaluated there:
//   contessa: iterate k: open O, stick S, slip P, signature H
// where H hashes every slave node's status and master facet. Two iterates with the same signature have
// the same active set, so the residual is one smooth function between them and Newton must converge
// quadratically there; where the signature changes, a node opened, closed, changed stick/slip or moved
// to another facet (a kink of the residual). tests/regression/friction/run_budget.py reads the lines to
// check the rate only where the active set stands still.
#include <ostream>

#include <NOX_Observer.hpp>

#include "continuation/ContactEventSource.hpp"

namespace contessa::solvers {

class IterateContactStates : public NOX::Observer {
 public:
  /// `print`: this rank writes the lines (rank 0); every rank takes part in gathering the states.
  IterateContactStates(const continuation::ContactEventSource& events, bool print, std::ostream& out)
      : events_(events), print_(print), out_(out) {}
  /// Iterate 0: its states are those of the evaluation before the first step.
  void runPreIterate(const NOX::Solver::Generic& solver) override;
  void runPostIterate(const NOX::Solver::Generic& solver) override;

 private:
  void report(int iterate);
  const continuation::ContactEventSource& events_;
  bool print_;
  std::ostream& out_;
};

}  // namespace contessa::solvers
