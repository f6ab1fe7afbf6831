// The adapter that continues LOCA from a restart file (solvers/LocaResume.hpp) re-seeds LOCA::Stepper's
// protected members as LOCA 13.2's start() sets them. That is not LOCA's interface: another Trilinos may
// set other members, or others in another order, and a restart would then no longer reproduce the
// uninterrupted run. This test fails on any other Trilinos version, naming what to re-check.
#include <gtest/gtest.h>

#include <type_traits>

#include <LOCA_Stepper.H>
#include <Trilinos_version.h>

#include "solvers/LocaResume.hpp"

namespace {

// The members ResumableStepper assigns, with the types it assigns: a rename or a change of type stops the
// build here, with this file's name in the error.
struct MembersProbe : contessa::solvers::ResumableStepper {
  static constexpr bool kTypesAsRelied =
      std::is_same_v<decltype(stepSize), double> && std::is_same_v<decltype(stepNumber), int> &&
      std::is_same_v<decltype(numFailedSteps), int> && std::is_same_v<decltype(numTotalSteps), int> &&
      std::is_same_v<decltype(curGroupPtr), Teuchos::RCP<LOCA::MultiContinuation::AbstractStrategy>> &&
      std::is_same_v<decltype(prevGroupPtr), Teuchos::RCP<LOCA::MultiContinuation::AbstractStrategy>> &&
      std::is_same_v<decltype(curPredictorPtr), Teuchos::RCP<LOCA::MultiContinuation::ExtendedVector>> &&
      std::is_same_v<decltype(prevPredictorPtr), Teuchos::RCP<LOCA::MultiContinuation::ExtendedVector>> &&
      std::is_same_v<decltype(solverPtr), Teuchos::RCP<NOX::Solver::Generic>> &&
      std::is_same_v<decltype(stepSizeStrategyPtr), Teuchos::RCP<LOCA::StepSize::AbstractStrategy>>;
};
static_assert(MembersProbe::kTypesAsRelied,
              "LOCA::Stepper's protected members changed: ResumableStepper (solvers/LocaResume.cpp) re-seeds them");

}  // namespace

TEST(LocaResume, WrittenForThisTrilinosVersion) {
  EXPECT_EQ(TRILINOS_MAJOR_MINOR_VERSION, contessa::solvers::kLocaInternalsVersion)
      << "Trilinos " << TRILINOS_VERSION_STRING << ": ResumableStepper::start() (solvers/LocaResume.cpp) replaces "
      << "LOCA::Stepper::start() of Trilinos 13.2 and re-seeds its protected members (curGroupPtr, prevGroupPtr, "
      << "curPredictorPtr, prevPredictorPtr, solverPtr, stepSize, stepNumber, numFailedSteps, numTotalSteps) and "
      << "LOCA's step-size strategy reads the Newton iterations of a ResumedSolver. Compare LOCA::Stepper::start() "
      << "of this version with it, run `ctest -L restart` (every restart must reproduce the uninterrupted run), "
      << "then set kLocaInternalsVersion.";
  EXPECT_EQ(MembersProbe::kTypesAsRelied, true);
}
