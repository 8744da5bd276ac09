// Errors: two tiers (STYLE "Input and errors").
//  - InputError: always on, for anything a user can get wrong; the message
//    names file, line, key, value and what was expected. main() catches it once.
//  - ANVIL_ASSERT: programmer errors, debug builds only.
#pragma once
#include <cassert>
#include <stdexcept>
#include <string>

namespace anvil {

/// A problem in user input (case file, mesh, material card). what() is the
/// complete message shown to the user.
class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A run that cannot continue (solver divergence, bad element during a run).
class RunError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// "file:line: message" when a line is known (line numbers start at 1).
std::string where(const std::string& file, int line = 0);

} // namespace anvil

#define ANVIL_ASSERT(cond) assert(cond)
