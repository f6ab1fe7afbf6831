// Material registry: one row per law. Adding a law = one class + one row here.
#include <array>

#include "common/Error.hpp"
#include "mechanics/LinearElastic.hpp"
#include "mechanics/Material.hpp"
#include "mechanics/NeoHookean.hpp"
#include "mechanics/SaintVenantKirchhoff.hpp"

namespace contessa::mechanics {
namespace {

struct MaterialEntry {
  const char* name;
  Teuchos::RCP<const Teuchos::ParameterList> (*validParameters)();
  std::unique_ptr<Material> (*create)(const Teuchos::ParameterList&, const std::string&);
};

template <class Law>
constexpr MaterialEntry entry() {
  return {Law::kModelName, &Law::validParameters, &Law::create};
}

constexpr std::array<MaterialEntry, 3> kRegistry = {
    entry<SaintVenantKirchhoff>(), entry<NeoHookean>(), entry<LinearElastic>()};

std::string knownNames() {
  std::string list;
  for (const auto& e : kRegistry) list += (list.empty() ? "" : ", ") + std::string(e.name);
  return list;
}

/// The registry row for `model`; throws InputError "<where>/Model: unknown ..." otherwise.
const MaterialEntry& lookup(const std::string& model, const std::string& where) {
  for (const auto& e : kRegistry)
    if (model == e.name) return e;
  const std::string prefix = where.empty() ? "Model" : where + "/Model";
  throw InputError(prefix + ": unknown material model '" + model + "' (known: " + knownNames() + ")");
}

}  // namespace

std::vector<std::string> MaterialFactory::names() {
  std::vector<std::string> result;
  for (const auto& e : kRegistry) result.emplace_back(e.name);
  return result;
}

Teuchos::RCP<const Teuchos::ParameterList> MaterialFactory::validParameters(const std::string& model) {
  return lookup(model, "").validParameters();
}

std::unique_ptr<Material> MaterialFactory::create(const Teuchos::ParameterList& params, const std::string& where) {
  requireInput(params.isType<std::string>("Model"),
               where + "/Model: required string parameter is missing (known: " + knownNames() + ")");
  return lookup(params.get<std::string>("Model"), where).create(params, where);
}

}  // namespace contessa::mechanics
