#include "mechanics/IsotropicElasticity.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/Error.hpp"

namespace contessa::mechanics {
namespace {

const char* const kYoung = "Young's Modulus";
const char* const kPoisson = "Poisson's Ratio";

std::string formatNumber(double value) {
  std::ostringstream os;
  os << value;
  return os.str();
}

/// A number entry as double; decks may spell integral values as int ("Young's Modulus: 200").
double readNumber(const Teuchos::ParameterList& params, const std::string& name, const std::string& where) {
  const std::string path = where + "/" + name;
  requireInput(params.isParameter(name), path + ": required parameter is missing");
  if (params.isType<double>(name)) return params.get<double>(name);
  if (params.isType<int>(name)) return params.get<int>(name);
  throw InputError(path + ": expected a number");
}

}  // namespace

LameConstants lameFromYoungPoisson(double youngsModulus, double poissonsRatio) {
  const double E = youngsModulus, nu = poissonsRatio;
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

Teuchos::RCP<Teuchos::ParameterList> isotropicElasticParameters(const std::string& model,
                                                                const std::string& description) {
  using Validator = Teuchos::EnhancedNumberValidator<double>;
  auto list = Teuchos::rcp(new Teuchos::ParameterList(model));
  list->set<std::string>("Model", model, description);
  // No meaningful default exists for E: 0 is published so the entry is documented, and create()
  // rejects it, so a deck that omits E fails with a message naming the parameter.
  list->set<double>(kYoung, 0.0, "Young's modulus E > 0 (required)",
                    Teuchos::rcp(new Validator(0.0, std::numeric_limits<double>::max())));
  list->set<double>(kPoisson, 0.0, "Poisson's ratio nu in (-1, 0.5)",
                    Teuchos::rcp(new Validator(-1.0, 0.5)));
  return list;
}

LameConstants readLameConstants(const Teuchos::ParameterList& params, const std::string& where) {
  const double E = readNumber(params, kYoung, where);
  requireInput(std::isfinite(E) && E > 0.0,
               where + "/" + kYoung + ": expected a value > 0, got " + formatNumber(E));
  // ν defaults to 0 like the published valid parameters (the list may not have been validated).
  const double nu = params.isParameter(kPoisson) ? readNumber(params, kPoisson, where) : 0.0;
  // ν → 0.5 makes λ infinite (incompressible) and ν ≤ −1 makes μ non-positive: both excluded.
  requireInput(std::isfinite(nu) && nu > -1.0 && nu < 0.5,
               where + "/" + kPoisson + ": expected a value in (-1, 0.5), got " + formatNumber(nu));
  return lameFromYoungPoisson(E, nu);
}

}  // namespace contessa::mechanics
