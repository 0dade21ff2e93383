#include "ceilplan/core/install_paths.hpp"

#include <system_error>
#include <vector>

namespace ceilplan {
namespace fs = std::filesystem;

namespace {

// GNUInstallDirs' directories under the prefix, as the build installs them (core/CMakeLists.txt).
const fs::path kBinDir = CEILPLAN_INSTALL_BINDIR;
const fs::path kDataDir = CEILPLAN_INSTALL_DATADIR;
const fs::path kDocDir = CEILPLAN_INSTALL_DOCDIR;

}  // namespace

fs::path runningExecutable() {
  std::error_code error;
  fs::path executable = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path() : executable;
}

std::optional<fs::path> installPrefix(const fs::path& executable) {
  if (executable.empty() || kBinDir.is_absolute()) return std::nullopt;
  // PREFIX/bin/NAME: strip bin's components from the executable's directory, one by one.
  fs::path prefix = executable.parent_path().lexically_normal();
  std::vector<fs::path> components(kBinDir.begin(), kBinDir.end());
  for (auto it = components.rbegin(); it != components.rend(); ++it) {
    if (prefix.filename() != *it) return std::nullopt;
    prefix = prefix.parent_path();
  }
  std::error_code error;
  if (!fs::is_directory(prefix / kDataDir / "ceilplan", error)) return std::nullopt;
  return prefix;
}

std::string docPage(const std::string& page, const fs::path& executable) {
  const auto prefix = installPrefix(executable);
  return prefix ? (*prefix / kDocDir / "docs" / page).string() : "docs/" + page;
}

std::string plotCommand(const std::string& script, const fs::path& executable) {
  const auto prefix = installPrefix(executable);
  return prefix ? (*prefix / kBinDir / ("ceilplan-" + script)).string() : "scripts/" + script;
}

}  // namespace ceilplan
