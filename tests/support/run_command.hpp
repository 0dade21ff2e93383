#pragma once
// Runs the `ceilplan` executable as a user would and captures what it says.

#include <sys/wait.h>
#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace ceilplan::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string readWholeFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Writes `bytes` to `path` as they are, creating its parent directories.
inline void writeWholeFile(const std::filesystem::path& path, const std::string& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

// `text` with every occurrence of each key of `values` replaced by its value ("{out}" -> a path).
inline std::string substituted(std::string text, const std::map<std::string, std::string>& values) {
  for (const auto& [key, value] : values)
    for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
      text.replace(at, key.size(), value);
  return text;
}

// A fresh scratch directory for one test, under the build tree.
inline std::filesystem::path scratchDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(CEILPLAN_TEST_TMP) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// `arguments` is passed through the shell after the executable's path; `shell_prefix`, if any,
// runs first in the same shell (e.g. "ulimit -v 1000000;").
inline CommandResult runCeilplan(const std::string& arguments, const std::string& shell_prefix = "") {
  const std::filesystem::path dir = std::filesystem::path(CEILPLAN_TEST_TMP);
  std::filesystem::create_directories(dir);
  static int calls = 0;  // tests run in parallel processes: pid + call count names the capture files
  const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(++calls);
  const auto out_path = dir / ("stdout_" + tag);
  const auto err_path = dir / ("stderr_" + tag);
  const std::string command = shell_prefix + " " + std::string(CEILPLAN_EXE) + " " + arguments + " </dev/null >" +
                              out_path.string() + " 2>" + err_path.string();
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = readWholeFile(out_path);
  result.err = readWholeFile(err_path);
  std::filesystem::remove(out_path);
  std::filesystem::remove(err_path);
  return result;
}

}  // namespace ceilplan::testing
