#include "output/RegularisationWarnings.hpp"

#include "common/NumberText.hpp"

namespace contessa::output {

std::vector<std::string> regularisationWarnings(const std::vector<contact::ContactInterfaceSpec>& contacts,
                                                const RegularisationByInterface& measures, int step, double lambda) {
  std::vector<std::string> out;
  const std::string where = " at step " + std::to_string(step) + " (load factor " + threeDigits(lambda) + ")";
  for (const auto& [name, m] : measures) {
    const contact::ContactInterfaceSpec* spec = nullptr;
    for (const auto& s : contacts)
      if (s.name == name && !s.secondPass) spec = &s;
    if (spec == nullptr) continue;
    const std::string path = "Problem/Contact/" + name + "/";
    if (contact::penetrationSpoils(m))
      out.push_back("contact interface '" + name + "': the penetration " + threeDigits(m.penetration) +
                    " exceeds a tenth of the largest slave displacement " + threeDigits(m.displacementScale) + where +
                    ": the normal penalty is too soft for this answer; raise " + path + "Normal Penalty");
    if (contact::elasticSlipSpoils(m))
      out.push_back("contact interface '" + name + "': the elastic slip " + threeDigits(m.elasticSlip) +
                    " exceeds a tenth of the mean slip " + threeDigits(m.meanSlip()) + " of its " +
                    std::to_string(static_cast<long long>(m.slippingNodes)) + " slipping nodes" + where +
                    ": the stick regularisation spoils the slip zone; " +
                    (spec->law.hasSlipTolerance() ? "lower " + path + "Slip Tolerance"
                                                  : "raise " + path + "Tangential Penalty"));
  }
  return out;
}

}  // namespace contessa::output
