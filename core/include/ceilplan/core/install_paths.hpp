#pragma once
// Where a message sends the user for a doc page or a figure script. From an installed ceilplan
// (cmake --install with any prefix, or the .deb) the source tree's docs/ and scripts/ are not
// there, so messages name the installed copies instead.

#include <filesystem>
#include <optional>
#include <string>

namespace ceilplan {

// The running program (/proc/self/exe): the `ceilplan` command line, or the Python interpreter
// that imported the module. Empty when the system does not say.
std::filesystem::path runningExecutable();

// The prefix ceilplan was installed into when `executable` lies in PREFIX/bin and PREFIX holds
// ceilplan's shipped data (PREFIX/share/ceilplan); empty for a program run from a build tree
// or an interpreter with no ceilplan installed beside it.
std::optional<std::filesystem::path> installPrefix(const std::filesystem::path& executable);

// A doc page ("missions.md") as the user can open it: PREFIX/share/doc/ceilplan/docs/missions.md
// from an install, docs/missions.md (in the source tree) otherwise.
std::string docPage(const std::string& page, const std::filesystem::path& executable = runningExecutable());

// A figure script ("plot-tour") as the user can run it: PREFIX/bin/ceilplan-plot-tour from an
// install, scripts/plot-tour (in the source tree) otherwise.
std::string plotCommand(const std::string& script, const std::filesystem::path& executable = runningExecutable());

}  // namespace ceilplan
