#pragma once
// The run says when the penalty regularisation spoils the answer (issue 21): at the end of the run, for
// each interface whose last converged increment has an elastic slip above a tenth of the mean slip of its
// slipping nodes, or a penetration above a tenth of the contact's displacement scale
// (contact::RegularisationMeasures), one line that names the interface and the deck parameter to change.
// Judged on the final state, the one a benchmark reads: in the first increments of a slip zone its few
// nodes slip less than the elastic slip whatever the tolerance, without spoiling the answer.
#include <string>
#include <utility>
#include <vector>

#include "contact/InterfaceSpec.hpp"
#include "contact/RegularisationMeasures.hpp"

namespace contessa::output {

/// Per interface, the measures of one converged increment (PostProcessing::contactRegularisation).
using RegularisationByInterface = std::vector<std::pair<std::string, contact::RegularisationMeasures>>;

/// The warnings for `measures` at step `step` (load factor `lambda`), one per interface and kind, without
/// the "contessa: warning: " prefix; `contacts` (the problem's specs) name the parameter to change.
std::vector<std::string> regularisationWarnings(const std::vector<contact::ContactInterfaceSpec>& contacts,
                                                const RegularisationByInterface& measures, int step, double lambda);

}  // namespace contessa::output
