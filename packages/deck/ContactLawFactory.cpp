// Contact law registry: one row per law (name, doc, parameters, build), on the common Registry.
#include "deck/ContactLawFactory.hpp"

#include <functional>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/Error.hpp"
#include "common/Registry.hpp"
#include "deck/ParameterValidation.hpp"

namespace contessa::deck {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

// ---- Penalty Coulomb: penalty normal law (eq. 16) and Coulomb friction by return mapping (eq. 17–23).

// The values of "Enforcement", in the order of ContactLawParameters::Enforcement.
const std::vector<std::string>& enforcementNames() {
  static const std::vector<std::string> names = {"Penalty", "Augmented Lagrangian"};
  return names;
}

RCP<ParameterList> penaltyCoulombParameters() {
  auto p = rcp(new ParameterList("Penalty Coulomb"));
  setNonNegative(*p, "Normal Penalty", 0.0,
                 "Normal penalty ε_N (pressure per unit penetration), eq. (16); 0 or not given = automatic: Penalty "
                 "Factor × the largest E'/h of the elements under the slave side (E' = E/(1 − ν²), h their "
                 "thickness under the side), printed at the start of the run");
  setPositive(*p, "Penalty Factor", 100.0,
              "The factor f of the automatic Normal Penalty ε_N = f × max E'/h (used only without a Normal Penalty)");
  setNonNegative(*p, "Tangential Penalty", 0.0,
                 "Tangential (stick) penalty ε_T, eq. (17): with Slip Tolerance = 0 the constant ε_T (0 or not given "
                 "= the Normal Penalty); with Slip Tolerance > 0 an upper bound of ε_T = μ|t_N|/(Slip Tolerance × "
                 "facet length) (0 = no bound)");
  setNonNegative(*p, "Friction Coefficient", 0.0, "Coulomb coefficient μ, eq. (18); 0 = frictionless");
  setBounded(*p, "Slip Tolerance", 0.005, 0.0, 1.0,
             "Allowable elastic slip while sticking, as a fraction of the slave facet length L (mean length of the "
             "slave sides at the node): "
             "the stick penalty is ε_T = μ|t_N|/(Slip Tolerance × L), so nearly unloaded nodes keep a finite stick "
             "range (as Abaqus' SLIP TOLERANCE); 0 = the paper's constant Tangential Penalty");
  setChoice(*p, "Enforcement", "Penalty", enforcementNames(),
            "Penalty: the penetration |t_N|/ε_N and the elastic slip of eq. (16)–(17) stay in the answer. Augmented "
            "Lagrangian: multipliers λ_N, λ_T added to the penalty tractions, t_N = min(0, λ_N + ε_N g_N), t_T "
            "return-mapped from λ_T + ε_T Δg_T, and updated to the converged tractions at the end of the increment "
            "(Uzawa) until Penetration Tolerance and Elastic Slip Tolerance hold, the increment solved again each "
            "time (docs/theory-contact.md §15)");
  setBounded(*p, "Penetration Tolerance", 1e-3, 0.0, 1.0,
             "Augmented Lagrangian: the largest penetration −g_N an increment may end with, as a fraction of the "
             "slave facet length L (0 = update until Max Augmentations)");
  setBounded(*p, "Elastic Slip Tolerance", 1e-4, 0.0, 1.0,
             "Augmented Lagrangian: the largest elastic slip ‖t_T − λ_T‖/ε_T of a sticking node in an increment, as "
             "a fraction of the slave facet length L (0 = update until Max Augmentations)");
  p->set("Max Augmentations", 10,
         "Augmented Lagrangian: the most multiplier updates per increment ([0, 1000]); an increment that still "
         "misses a tolerance then is accepted and the run says so once per interface",
         rcp(new Teuchos::EnhancedNumberValidator<int>(0, 1000)));
  return p;
}

contact::ContactLawParameters createPenaltyCoulomb(const ParameterList& list, const std::string& /*where*/) {
  contact::ContactLawParameters law;
  law.normalPenalty = list.get<double>("Normal Penalty");
  law.tangentialPenalty = list.get<double>("Tangential Penalty");
  law.frictionCoefficient = list.get<double>("Friction Coefficient");
  law.slipTolerance = list.get<double>("Slip Tolerance");
  law.enforcement = list.get<std::string>("Enforcement") == enforcementNames().back()
                        ? contact::ContactLawParameters::Enforcement::AugmentedLagrangian
                        : contact::ContactLawParameters::Enforcement::Penalty;
  law.penetrationTolerance = list.get<double>("Penetration Tolerance");
  law.elasticSlipTolerance = list.get<double>("Elastic Slip Tolerance");
  law.maxAugmentations = list.get<int>("Max Augmentations");
  // Normal Penalty 0: automatic, set from the elements under the slave side (deck/AutomaticPenalty.hpp);
  // a constant stick penalty left out is the normal one (set there too when that is automatic).
  if (!law.isFrictionless() && !law.hasSlipTolerance() && law.tangentialPenalty == 0)
    law.tangentialPenalty = law.normalPenalty;
  return law;
}

// A law's row: its deck parameters and what makes its ContactLawParameters (common/Registry.hpp).
struct LawFactory {
  RCP<ParameterList> (*parameters)();
  contact::ContactLawParameters (*create)(const ParameterList&, const std::string&);
};
using LawRow = RegistryRow<LawFactory>;

const Registry<LawRow>& registry() {
  static const Registry<LawRow> rows(
      "contact law",
      {{"Penalty Coulomb",
        "Penalty normal contact, t_N = ε_N g_N for a penetration g_N < 0 (eq. 16), and Coulomb friction by return "
        "mapping (eq. 17–23): stick with the penalty ε_T while |t_T| < μ|t_N|, slip on the cone otherwise; the "
        "stick penalty follows the pressure through Slip Tolerance (docs/theory-contact.md §5); without a Normal "
        "Penalty, ε_N comes from the stiffness of the elements under the slave side (§5.3)",
        {penaltyCoulombParameters, createPenaltyCoulomb}}});
  return rows;
}

}  // namespace

std::vector<std::string> ContactLawFactory::names() { return registry().names(); }

std::string ContactLawFactory::description(const std::string& law) { return registry().lookup(law, "Law").doc; }

RCP<const ParameterList> ContactLawFactory::validParameters(const std::string& law) {
  return registry().lookup(law, "Law").factory.parameters();
}

contact::ContactLawParameters ContactLawFactory::create(const std::string& law, const ParameterList& params,
                                                        const std::string& where) {
  return registry().lookup(law, where + "/Law").factory.create(params, where);
}

}  // namespace contessa::deck
