// What a step-size method adds to the continuation through its registry row (solvers/StepControl.hpp):
// LOCA's own methods add nothing; Contact Beta's row adds its strategy, its Restart-mode test, its
// convergence veto and its stop words, and changes the model's state only in iterateSet (before the
// status tests), never in a test. Its parameters are declared once with the defaults of
// continuation::ContactBetaSettings.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <vector>

#include <LOCA_StepSize_AbstractStrategy.H>
#include <NOX_Abstract_Group.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Generic.H>
#include <NOX_Thyra_Vector.H>
#include <Thyra_DefaultSpmdVectorSpace.hpp>

#include "continuation/ContactBetaControl.hpp"
#include "continuation/ContactEventSource.hpp"
#include "solvers/ContactBetaStepControl.hpp"
#include "solvers/ResumableStepSize.hpp"
#include "solvers/StepControl.hpp"
#include "solvers/StepSizeMethods.hpp"

namespace cb = contessa::continuation;
using contessa::StateRecord;
using contessa::solvers::ContactBetaStepControl;
using contessa::solvers::StepControl;
using contessa::solvers::StepControlContext;

namespace {

// Slave nodes as the model would report them; records the freeze switch.
class FakeEvents : public cb::ContactEventSource {
 public:
  std::vector<cb::SlaveNodeIncrement> trialIncrement() const override { return trial; }
  std::vector<cb::SlaveNodeIncrement> trialIncrementAt(const Thyra::VectorBase<double>&, double) const override {
    return trial;
  }
  std::vector<cb::SlaveNodeIncrement> committedIncrement() const override { return {}; }
  void freezeNewContacts(bool f) override { frozen = f; }
  bool newContactsFrozen() const override { return frozen; }
  std::vector<cb::SlaveNodeIncrement> trial;
  bool frozen = false;
};

// A Newton group that counts its residual evaluations and notes whether new contacts were frozen at each.
class CountingGroup : public NOX::Abstract::Group {
 public:
  explicit CountingGroup(const FakeEvents& events)
      : events_(events),
        x_(Teuchos::rcp(new NOX::Thyra::Vector(Thyra::createMember<double>(
            Teuchos::rcp_implicit_cast<const Thyra::VectorSpaceBase<double>>(Thyra::defaultSpmdVectorSpace<double>(2)))))) {}
  NOX::Abstract::Group& operator=(const NOX::Abstract::Group&) override { throw std::logic_error("unused"); }
  void setX(const NOX::Abstract::Vector& y) override {
    *x_ = y;
    validF_ = false;
  }
  void computeX(const NOX::Abstract::Group&, const NOX::Abstract::Vector&, double) override {
    throw std::logic_error("unused");
  }
  ReturnType computeF() override {
    if (validF_) return Ok;
    frozenAtEvaluation.push_back(events_.frozen);
    validF_ = true;
    return Ok;
  }
  bool isF() const override { return validF_; }
  const NOX::Abstract::Vector& getX() const override { return *x_; }
  const NOX::Abstract::Vector& getF() const override { return *x_; }
  double getNormF() const override { return 0; }
  const NOX::Abstract::Vector& getGradient() const override { throw std::logic_error("unused"); }
  const NOX::Abstract::Vector& getNewton() const override { throw std::logic_error("unused"); }
  Teuchos::RCP<const NOX::Abstract::Vector> getXPtr() const override { return x_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getFPtr() const override { return x_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getGradientPtr() const override { throw std::logic_error("unused"); }
  Teuchos::RCP<const NOX::Abstract::Vector> getNewtonPtr() const override { throw std::logic_error("unused"); }
  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType) const override { throw std::logic_error("unused"); }

  std::vector<bool> frozenAtEvaluation;  ///< one entry per residual evaluation

 private:
  const FakeEvents& events_;
  Teuchos::RCP<NOX::Abstract::Vector> x_;
  bool validF_ = false;
};

// A Newton solver at a given iteration on a given group: what a status test reads.
class SolverAt : public NOX::Solver::Generic {
 public:
  SolverAt(const NOX::Abstract::Group& group, int iteration) : group_(group), iteration_(iteration) {}
  void reset() override {}
  void reset(const NOX::Abstract::Vector&) override {}
  void reset(const NOX::Abstract::Vector&, const Teuchos::RCP<NOX::StatusTest::Generic>&) override {}
  NOX::StatusTest::StatusType step() override { throw std::logic_error("unused"); }
  NOX::StatusTest::StatusType solve() override { throw std::logic_error("unused"); }
  const NOX::Abstract::Group& getSolutionGroup() const override { return group_; }
  const NOX::Abstract::Group& getPreviousSolutionGroup() const override { return group_; }
  NOX::StatusTest::StatusType getStatus() const override { return NOX::StatusTest::Unconverged; }
  int getNumIterations() const override { return iteration_; }
  const Teuchos::ParameterList& getList() const override { return list_; }
  Teuchos::RCP<const NOX::Abstract::Group> getSolutionGroupPtr() const override { return Teuchos::rcpFromRef(group_); }
  Teuchos::RCP<const NOX::Abstract::Group> getPreviousSolutionGroupPtr() const override {
    return Teuchos::rcpFromRef(group_);
  }
  Teuchos::RCP<const Teuchos::ParameterList> getListPtr() const override { return Teuchos::rcpFromRef(list_); }
  Teuchos::RCP<const NOX::SolverStats> getSolverStatistics() const override { return Teuchos::null; }

 private:
  const NOX::Abstract::Group& group_;
  int iteration_;
  Teuchos::ParameterList list_;
};

// The validated Step Size list of a deck that sets Method (and what `set` adds).
Teuchos::ParameterList stepSizeList(const std::string& method, const std::function<void(Teuchos::ParameterList&)>& set = {}) {
  Teuchos::ParameterList list;
  contessa::solvers::addStepSizeParameters(list);
  list.set("Method", method);
  if (set) set(list);
  return list;
}

/// Open node closing at β^k = b of the planned step (g_t = b, trial g = b − 1).
cb::SlaveNodeIncrement closingAt(double b) {
  cb::SlaveNodeIncrement n;
  n.committedGap = b;
  n.trialGap = b - 1.0;
  n.trialStatus = b <= 1.0 ? cb::NodeStatus::Stick : cb::NodeStatus::Open;
  return n;
}

// Contact Beta's control in the state of a first attempt of 0.125 from λ = 0 whose first iterate is to be
// checked (Restart mode), as a restart file would put it back.
void pendingCheck(StepControl& control, const std::function<void(StateRecord&)>& more = {}) {
  auto strategy = control.createStrategy();
  auto* resumable = dynamic_cast<contessa::solvers::ResumableStepSize*>(strategy.get());
  ASSERT_NE(resumable, nullptr);
  StateRecord state;
  resumable->saveState(state);
  auto& beta = state.child("contact_beta");
  beta.put("step", std::vector<double>{0.125}, {});
  beta.put("planned_step", std::vector<double>{0.125}, {});
  beta.put("check_pending", std::vector<std::int64_t>{1}, {});
  if (more) more(beta);
  resumable->loadState(state);
}

}  // namespace

TEST(StepControl, LocaMethodsAddNothing) {
  FakeEvents events;
  for (const std::string method : {"Constant", "Adaptive"}) {
    const auto list = stepSizeList(method);
    auto control = contessa::solvers::createStepControl(StepControlContext{list, 1.0, events});
    EXPECT_TRUE(control->createStrategy().is_null()) << method;  // LOCA builds its own
    EXPECT_TRUE(control->correctionTest().is_null()) << method;
    EXPECT_EQ(control->redoAtConvergence(), "") << method;
    EXPECT_EQ(control->stopReason(), "") << method;
    EXPECT_EQ(control->correctionFactor(), 1.0) << method;
    EXPECT_FALSE(control->correctionRequested()) << method;
    EXPECT_TRUE(control->mayConverge()) << method;
    EXPECT_TRUE(control->updateMeaningful()) << method;
    // No iterate is ever asked for: the group accessor would throw.
    control->iterateSet([]() -> NOX::Abstract::Group& { throw std::logic_error("asked for the group"); }, 1);
    EXPECT_FALSE(events.frozen);
  }
}

TEST(StepControl, ContactBetaRowAddsItsStrategyTestAndVeto) {
  FakeEvents events;
  const auto restart = stepSizeList("Contact Beta");
  auto control = contessa::solvers::createStepControl(StepControlContext{restart, 1.0, events});
  ASSERT_NE(dynamic_cast<ContactBetaStepControl*>(control.get()), nullptr);
  EXPECT_FALSE(control->createStrategy().is_null());
  EXPECT_FALSE(control->correctionTest().is_null());  // Restart mode (the default): the first-iterate test
  EXPECT_NE(control->correctionName().find("Contact Beta"), std::string::npos);
  events.frozen = true;
  EXPECT_FALSE(control->mayConverge());  // not while new contacts are frozen
  events.frozen = false;
  EXPECT_TRUE(control->mayConverge());

  const auto predictor = stepSizeList("Contact Beta", [](Teuchos::ParameterList& l) { l.set("Mode", "Predictor"); });
  auto predicting = contessa::solvers::createStepControl(StepControlContext{predictor, 1.0, events});
  EXPECT_TRUE(predicting->correctionTest().is_null());  // no restart in Predictor mode
}

TEST(StepControl, ContactsPerStepIsDeclaredOnceWithTheSettingsDefault) {
  const auto list = stepSizeList("Contact Beta");
  EXPECT_EQ(list.get<int>("Contacts Per Step"), cb::BetaOptions().contactsPerStep);
  EXPECT_EQ(list.get<double>("Next Contact Fraction"), cb::BetaOptions().nextContactFraction);
  EXPECT_EQ(list.get<double>("Restart Tolerance"), cb::ContactBetaSettings().restartTolerance);
  EXPECT_EQ(list.get<int>("Max Corrections Per Increment"), cb::ContactBetaSettings().maxCorrections);
  const auto three = stepSizeList("Contact Beta", [](Teuchos::ParameterList& l) { l.set("Contacts Per Step", 3); });
  EXPECT_EQ(ContactBetaStepControl::settings(three, 0.5).beta.contactsPerStep, 3);
  EXPECT_EQ(ContactBetaStepControl::settings(three, 0.5).finalLoadFactor, 0.5);
}

TEST(StepControl, ContactBetaSwitchesContactsOnBeforeTheTestsWhenTheStepStands) {
  FakeEvents events;
  const auto list = stepSizeList("Contact Beta");
  ContactBetaStepControl control(StepControlContext{list, 1.0, events});
  pendingCheck(control);
  ASSERT_TRUE(control.control().checkPending());
  events.frozen = true;  // the attempt's first iterate was computed without new contacts
  CountingGroup group(events);
  // β^k = 0.25, 0.875, 1.125 with N_c = 2, f = 0.9: β = 0.875 + 0.9 × 0.25 = 1.1; the planned step lies at
  // (1 − 0.875)/0.25 = 0.5 of the way to the third event, within [0.45, 0.95): it stands.
  events.trial = {closingAt(0.25), closingAt(0.875), closingAt(1.125)};
  control.startIterate();
  control.iterateSet([&group]() -> NOX::Abstract::Group& { return group; }, 2);  // not the first iterate
  EXPECT_TRUE(group.frozenAtEvaluation.empty());
  control.iterateSet([&group]() -> NOX::Abstract::Group& { return group; }, 1);
  // f at the iterate with new contacts frozen (β measured there), then again with them switched on.
  EXPECT_EQ(group.frozenAtEvaluation, (std::vector<bool>{true, false}));
  EXPECT_TRUE(group.isF());
  EXPECT_FALSE(events.frozen);
  EXPECT_FALSE(control.firstIterateRejected());
  EXPECT_FALSE(control.updateMeaningful());  // this iterate's update was computed without the new contacts
  EXPECT_FALSE(control.control().checkPending());
  control.startIterate();
  EXPECT_TRUE(control.updateMeaningful());
}

TEST(StepControl, ContactBetaRejectsTheFirstIterateWithoutTouchingTheModel) {
  FakeEvents events;
  const auto list = stepSizeList("Contact Beta");
  ContactBetaStepControl control(StepControlContext{list, 1.0, events});
  pendingCheck(control);
  events.frozen = true;
  CountingGroup group(events);
  // β^k = 0.25, 0.5, 0.75: the planned step takes 3 events, N_c = 2: restart with β = 0.5 + 0.9 × 0.25.
  events.trial = {closingAt(0.25), closingAt(0.5), closingAt(0.75)};
  control.startIterate();
  control.iterateSet([&group]() -> NOX::Abstract::Group& { return group; }, 1);
  EXPECT_EQ(group.frozenAtEvaluation, (std::vector<bool>{true}));
  EXPECT_TRUE(events.frozen);
  EXPECT_TRUE(control.firstIterateRejected());
  EXPECT_TRUE(control.correctionRequested());
  EXPECT_EQ(control.correctionFactor(), 0.5 + 0.9 * 0.25);
  control.startIterate();
  EXPECT_FALSE(control.firstIterateRejected());
}

TEST(StepControl, ContactBetaStopWordsNameNc) {
  FakeEvents events;
  const auto list = stepSizeList("Contact Beta", [](Teuchos::ParameterList& l) { l.set("Contacts Per Step", 3); });
  ContactBetaStepControl control(StepControlContext{list, 1.0, events});
  EXPECT_EQ(control.stopReason(), "");
  pendingCheck(control, [](StateRecord& beta) { beta.put("hit_minimum_step", std::vector<std::int64_t>{1}, {}); });
  EXPECT_EQ(control.stopReason(),
            "Contact Beta asked for a step below Min Step Size = 1e-06 to let only 3 contacts close per increment");
}

TEST(StepControl, ContactBetaRestartTestOnlyTests) {
  FakeEvents events;
  const auto list = stepSizeList("Contact Beta");
  ContactBetaStepControl control(StepControlContext{list, 1.0, events});
  auto test = control.correctionTest();
  ASSERT_FALSE(test.is_null());
  pendingCheck(control);
  events.frozen = true;
  CountingGroup group(events);
  const SolverAt first(group, 1);
  // A first iterate that reaches the test unchecked (no iterateSet before it) is a wiring error, not a pass.
  EXPECT_THROW(test->checkStatus(first, NOX::StatusTest::Minimal), std::logic_error);

  events.trial = {closingAt(0.25), closingAt(0.5), closingAt(0.75)};  // restart (as above)
  control.startIterate();
  control.iterateSet([&group]() -> NOX::Abstract::Group& { return group; }, 1);
  const auto evaluations = group.frozenAtEvaluation.size();
  EXPECT_EQ(test->checkStatus(first, NOX::StatusTest::Minimal), NOX::StatusTest::Failed);
  EXPECT_EQ(group.frozenAtEvaluation.size(), evaluations);  // the test evaluated nothing
  EXPECT_TRUE(events.frozen);                                // and switched nothing
  control.startIterate();
  const SolverAt second(group, 2);
  EXPECT_EQ(test->checkStatus(second, NOX::StatusTest::Minimal), NOX::StatusTest::Unconverged);
}
