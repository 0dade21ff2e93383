#pragma once
/// @file
/// How long work reports progress: the library calls back, the application draws (or not).

#include <functional>
#include <string>

namespace ceilplan {

/// `stage` names the step ("ceiling mode: building the roadmap"), `fraction` in [0, 1] is how
/// much of it is done; a stage ends with fraction 1. Called from the thread that started the work.
using ProgressCallback = std::function<void(const std::string& stage, double fraction)>;

}  // namespace ceilplan
