#include "output/RegularisationWarnings.hpp"

#include <cstdio>

namespace contessa::output {
namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

std::vector<std::string> regularisationWarnings(const std::vector<contact::ContactInterfaceSpec>& contacts,
                                                const RegularisationByInterface& measures, int step, double lambda) {
  std::vector<std::string> out;
  const std::string where = " at step " + std::to_string(step) + " (load factor " + number(lambda) + ")";
  for (const auto& [name, m] : measures) {
    const contact::ContactInterfaceSpec* spec = nullptr;
    for (const auto& s : contacts)
      if (s.name == name && !s.secondPass) spec = &s;
    if (spec == nullptr) continue;
    const std::string path = "Problem/Contact/" + name + "/";
    if (contact::penetrationSpoils(m))
      out.push_back("contact interface '" + name + "': the penetration " + number(m.penetration) +
                    " exceeds a tenth of the largest slave displacement " + number(m.displacementScale) + where +
                    ": the normal penalty is too soft for this answer; raise " + path + "Normal Penalty");
    if (contact::elasticSlipSpoils(m))
      out.push_back("contact interface '" + name + "': the elastic slip " + number(m.elasticSlip) +
                    " exceeds a tenth of the mean slip " + number(m.meanSlip()) + " of its " +
                    std::to_string(static_cast<long long>(m.slippingNodes)) + " slipping nodes" + where +
                    ": the stick regularisation spoils the slip zone; " +
                    (spec->law.hasSlipTolerance() ? "lower " + path + "Slip Tolerance"
                                                  : "raise " + path + "Tangential Penalty"));
  }
  return out;
}

}  // namespace contessa::output
