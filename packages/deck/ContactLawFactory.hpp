#pragma once
// Contact laws by name ("Problem/Contact/<name>/Law"): one registry row each (ContactLawFactory.cpp) with
// what the law is, the deck parameters it takes (docs, defaults, ranges) and the function that turns a
// validated list into the law's parameters for the contact element. Today one law: penalty normal
// contact with Coulomb friction (the paper's eq. 16–23, with the elastic-slip tolerance), the default, so
// decks without Law read as before. The deck validates an interface against the common contact parameters
// plus its law's; the deck reference is generated from the rows. Adding a law = its parameters struct and
// element path + one row.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "contact/ContactLawParameters.hpp"

namespace contessa::deck {

class ContactLawFactory {
 public:
  /// Registered names, the default first: "Penalty Coulomb".
  static std::vector<std::string> names();
  static std::string defaultLaw() { return names().front(); }
  /// What the law is (one paragraph, for the deck reference).
  static std::string description(const std::string& law);
  /// The law's parameters with docs and defaults, without "Law" itself. Throws InputError listing the
  /// known names for an unknown law.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters(const std::string& law);
  /// The law's parameters from `params` (validated against validParameters(law)); `where` is the deck
  /// path of the interface: an inconsistent combination is an InputError "<where>/<parameter>: ...".
  static contact::ContactLawParameters create(const std::string& law, const Teuchos::ParameterList& params,
                                              const std::string& where);
};

}  // namespace contessa::deck
