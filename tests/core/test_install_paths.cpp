// Messages that send the user to a doc page or a figure script name the source tree's docs/ and
// scripts/ when ceilplan runs from a build tree, and the installed copies when it runs from an
// install (any prefix): PREFIX/bin/ceilplan beside PREFIX/share/ceilplan.
#include "ceilplan/core/install_paths.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "run_command.hpp"

namespace ceilplan::testing {
namespace {

namespace fs = std::filesystem;

// An install's skeleton under a scratch prefix: the data directory that marks it, and an empty bin/.
fs::path fakeInstall(const std::string& name) {
  fs::path prefix = scratchDirectory(name) / "prefix";
  fs::create_directories(prefix / "share/ceilplan/maps");
  fs::create_directories(prefix / "bin");
  return prefix;
}

TEST(InstallPaths, AnExecutableInAPrefixThatHoldsCeilplansDataIsAnInstall) {
  const fs::path prefix = fakeInstall("install");
  EXPECT_EQ(installPrefix(prefix / "bin/ceilplan"), prefix);
  EXPECT_EQ(docPage("missions.md", prefix / "bin/ceilplan"), (prefix / "share/doc/ceilplan/docs/missions.md").string());
  EXPECT_EQ(plotCommand("plot-tour", prefix / "bin/ceilplan"), (prefix / "bin/ceilplan-plot-tour").string());
}

TEST(InstallPaths, ABuildTreeExecutableNamesTheSourceTreesDocsAndScripts) {
  const fs::path build = scratchDirectory("build_tree");
  fs::create_directories(build / "app");
  EXPECT_FALSE(installPrefix(build / "app/ceilplan"));
  EXPECT_EQ(docPage("missions.md", build / "app/ceilplan"), "docs/missions.md");
  EXPECT_EQ(plotCommand("plot-tour", build / "app/ceilplan"), "scripts/plot-tour");
}

TEST(InstallPaths, ABinDirectoryWithoutCeilplansDataBesideItIsNoInstall) {
  // An interpreter in /usr/bin (or any bin/) that imported a build tree's module.
  const fs::path prefix = scratchDirectory("no_data") / "prefix";
  fs::create_directories(prefix / "bin");
  EXPECT_FALSE(installPrefix(prefix / "bin/python3"));
  EXPECT_FALSE(installPrefix(fs::path()));
  EXPECT_EQ(plotCommand("plot-compare", prefix / "bin/python3"), "scripts/plot-compare");
}

TEST(InstallPaths, TheRunningExecutableIsThisProgram) { EXPECT_EQ(runningExecutable().filename(), "test_core"); }

TEST(InstallPaths, TheCommandLineCopiedIntoAPrefixPointsItsHelpAtTheInstalledDocs) {
  const fs::path prefix = fakeInstall("cli");
  fs::copy_file(CEILPLAN_EXE, prefix / "bin/ceilplan");
  const fs::path help = prefix.parent_path() / "help.txt";
  const std::string command = (prefix / "bin/ceilplan").string() + " tour --help >" + help.string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_NE(
      readWholeFile(help).find("mission file (" + (prefix / "share/doc/ceilplan/docs/missions.md").string() + ")"),
      std::string::npos)
      << readWholeFile(help);
  // The build tree's own executable keeps the source tree's relative path.
  EXPECT_NE(runCeilplan("tour --help").out.find("mission file (docs/missions.md)"), std::string::npos);
}

}  // namespace
}  // namespace ceilplan::testing
