#pragma once
// The one-line message a piece of library code refuses its input with, for tests that state
// what it must say.

#include "ceilplan/core/error.hpp"

#include <string>

namespace ceilplan::testing {

// The message of the ceilplan::InputError `action` throws, or "(no error)".
template <class Action>
std::string inputErrorOf(const Action& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace ceilplan::testing
