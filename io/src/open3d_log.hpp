#pragma once
// Open3D reports why a read failed through its global logger (to stdout by default), and the C
// readers inside it (RPly) print to stderr. failureOf captures both for one read, so the
// library stays quiet and the error can say what Open3D found. Private to the io module.

#include <functional>
#include <optional>
#include <string>

namespace ceilplan::io::detail {

// Runs one Open3D read (returning Open3D's success flag) while capturing its messages: nothing
// on success, else what Open3D said, joined by "; " (possibly empty). Open3D errors thrown as
// exceptions count as failures too. One read at a time in the process; stderr is redirected
// for its duration.
std::optional<std::string> failureOf(const std::function<bool()>& read);

}  // namespace ceilplan::io::detail
