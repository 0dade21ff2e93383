#pragma once

namespace ceilplan::app {

// Exit codes of the `ceilplan` executable (docs/cli.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   // a runtime failure: a computation or a write failed
inline constexpr int kExitBadInput = 2;  // bad input or usage: a file, key, flag or value is wrong
inline constexpr int kExitNoPath = 3;    // no path, or a well-formed request that cannot be met (infeasible)

}  // namespace ceilplan::app
