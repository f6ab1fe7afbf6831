// Contact law registry: one row per law (name, description, parameters, build).
#include "deck/ContactLawFactory.hpp"

#include <functional>

#include "common/Error.hpp"
#include "deck/ParameterValidation.hpp"

namespace contessa::deck {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

// ---- Penalty Coulomb: penalty normal law (eq. 16) and Coulomb friction by return mapping (eq. 17–23).

RCP<ParameterList> penaltyCoulombParameters() {
  auto p = rcp(new ParameterList("Penalty Coulomb"));
  setNonNegative(*p, "Normal Penalty", 0.0, "Normal penalty ε_N (pressure per unit penetration), eq. (16); required");
  setNonNegative(*p, "Tangential Penalty", 0.0,
                 "Tangential (stick) penalty ε_T, eq. (17): with Slip Tolerance = 0 the constant ε_T (required when "
                 "Friction Coefficient > 0); with Slip Tolerance > 0 an upper bound of ε_T = μ|t_N|/(Slip Tolerance × "
                 "facet length) (0 = no bound)");
  setNonNegative(*p, "Friction Coefficient", 0.0, "Coulomb coefficient μ, eq. (18); 0 = frictionless");
  setBounded(*p, "Slip Tolerance", 0.005, 0.0, 1.0,
             "Allowable elastic slip while sticking, as a fraction of the slave facet length L (mean length of the "
             "slave sides at the node): "
             "the stick penalty is ε_T = μ|t_N|/(Slip Tolerance × L), so nearly unloaded nodes keep a finite stick "
             "range (as Abaqus' SLIP TOLERANCE); 0 = the paper's constant Tangential Penalty");
  return p;
}

contact::ContactLawParameters createPenaltyCoulomb(const ParameterList& list, const std::string& where) {
  contact::ContactLawParameters law;
  law.normalPenalty = list.get<double>("Normal Penalty");
  law.tangentialPenalty = list.get<double>("Tangential Penalty");
  law.frictionCoefficient = list.get<double>("Friction Coefficient");
  law.slipTolerance = list.get<double>("Slip Tolerance");
  requireInput(law.normalPenalty > 0, where + "/Normal Penalty: required; expected a value > 0");
  requireInput(law.frictionCoefficient == 0 || law.slipTolerance > 0 || law.tangentialPenalty > 0,
               where + "/Tangential Penalty: expected a value > 0 when Friction Coefficient > 0 and Slip Tolerance = 0");
  return law;
}

struct LawEntry {
  const char* name;
  const char* description;
  RCP<ParameterList> (*parameters)();
  contact::ContactLawParameters (*create)(const ParameterList&, const std::string&);
};

const std::vector<LawEntry>& registry() {
  static const std::vector<LawEntry> rows = {
      {"Penalty Coulomb",
       "Penalty normal contact, t_N = ε_N g_N for a penetration g_N < 0 (eq. 16), and Coulomb friction by return "
       "mapping (eq. 17–23): stick with the penalty ε_T while |t_T| < μ|t_N|, slip on the cone otherwise; the "
       "stick penalty follows the pressure through Slip Tolerance (docs/theory-contact.md §5)",
       penaltyCoulombParameters, createPenaltyCoulomb},
  };
  return rows;
}

const LawEntry& entry(const std::string& law) {
  for (const auto& row : registry())
    if (law == row.name) return row;
  std::string known;
  for (const auto& row : registry()) known += (known.empty() ? "" : ", ") + std::string(row.name);
  throw InputError("unknown contact law '" + law + "' (known: " + known + ")");
}

}  // namespace

std::vector<std::string> ContactLawFactory::names() {
  std::vector<std::string> out;
  for (const auto& row : registry()) out.push_back(row.name);
  return out;
}

std::string ContactLawFactory::description(const std::string& law) { return entry(law).description; }

RCP<const ParameterList> ContactLawFactory::validParameters(const std::string& law) { return entry(law).parameters(); }

contact::ContactLawParameters ContactLawFactory::create(const std::string& law, const ParameterList& params,
                                                        const std::string& where) {
  return entry(law).create(params, where);
}

}  // namespace contessa::deck
