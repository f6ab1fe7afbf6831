#pragma once
// Deck validation against the valid-parameter lists that every configurable class publishes
// (MOOSE validParams, Teuchos validateParametersAndSetDefaults), with one-line errors that name the
// deck path: an unknown or mistyped name, a wrong type, a value out of range.
#include <set>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "common/ParameterPublishing.hpp"

namespace contessa::deck {

/// "a/b" from "a" and "b" (no leading slash when `parent` is empty).
std::string joinPath(const std::string& parent, const std::string& name);

/// Checks every entry of `deck` against `valid` and fills in the defaults of entries the deck
/// leaves out. `path` names `deck` in messages. Sublists named in `openSublists` are skipped (their
/// children are user-named and validated by the caller); a name "A/B" there is B within A. An int given where a double is expected is
/// converted. Throws contessa::InputError with a one-line message on the first problem.
void validateAndSetDefaults(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid,
                            const std::string& path, const std::set<std::string>& openSublists = {});

/// The value of a validator-checked string parameter must be one of `allowed`; throws InputError
/// "PATH: expected one of A, B, C; got 'X'" otherwise.
void requireOneOf(const std::string& path, const std::string& value, const std::vector<std::string>& allowed);

/// Helpers to publish parameters with a documented range (the validator documents the range in the
/// deck reference; validateAndSetDefaults enforces it). setPositive, setPositiveInt and setChoice are
/// common/ParameterPublishing's, shared with the packages below the deck.
using contessa::setChoice;
using contessa::setPositive;
using contessa::setPositiveInt;
void setNonNegative(Teuchos::ParameterList& list, const std::string& name, double value, const std::string& doc);
void setBounded(Teuchos::ParameterList& list, const std::string& name, double value, double min, double max,
                const std::string& doc);

}  // namespace contessa::deck
