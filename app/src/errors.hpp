#pragma once

#include <stdexcept>

namespace ceilplan::app {

// Exit codes of the `ceilplan` executable (documented in docs/cli.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitInputError = 1;  // bad input or a failed computation, with a one-line reason
inline constexpr int kExitUsage = 2;       // unknown flag, missing argument, malformed config file
inline constexpr int kExitNoPath = 3;      // the planner proved or gave up on finding a path

}  // namespace ceilplan::app
