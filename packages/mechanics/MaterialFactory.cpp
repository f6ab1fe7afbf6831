// Material registry: one row per law. Adding a law = one class + one row here.
#include "common/Error.hpp"
#include "common/Registry.hpp"
#include "mechanics/LinearElastic.hpp"
#include "mechanics/Material.hpp"
#include "mechanics/NeoHookean.hpp"
#include "mechanics/SaintVenantKirchhoff.hpp"

namespace contessa::mechanics {
namespace {

// A law publishes its parameters and is made from them.
struct MaterialMaker {
  Teuchos::RCP<const Teuchos::ParameterList> (*validParameters)();
  std::unique_ptr<Material> (*create)(const Teuchos::ParameterList&, const std::string&);
};

template <class Law>
RegistryRow<MaterialMaker> row(const char* doc) {
  return {Law::kModelName, doc, {&Law::validParameters, &Law::create}};
}

const Registry<RegistryRow<MaterialMaker>>& registry() {
  static const Registry<RegistryRow<MaterialMaker>> rows(
      "material model", {row<SaintVenantKirchhoff>("S = λ tr(E) I + 2μ E: large rotations with small strains"),
                         row<NeoHookean>("compressible, W = μ/2 (tr C − 3) − μ ln J + λ/2 (ln J)²: large strains"),
                         row<LinearElastic>("σ = λ tr(ε) I + 2μ ε, geometrically linear: small strains and rotations")});
  return rows;
}

/// The parameter that names the law: "<where>/Model", or "Model" without a path.
std::string modelParameter(const std::string& where) { return where.empty() ? "Model" : where + "/Model"; }

}  // namespace

std::vector<std::string> MaterialFactory::names() { return registry().names(); }

Teuchos::RCP<const Teuchos::ParameterList> MaterialFactory::validParameters(const std::string& model) {
  return registry().lookup(model, modelParameter("")).factory.validParameters();
}

std::unique_ptr<Material> MaterialFactory::create(const Teuchos::ParameterList& params, const std::string& where) {
  requireInput(params.isType<std::string>("Model"),
               where + "/Model: required string parameter is missing (known: " + registry().knownNames() + ")");
  return registry().lookup(params.get<std::string>("Model"), modelParameter(where)).factory.create(params, where);
}

}  // namespace contessa::mechanics
