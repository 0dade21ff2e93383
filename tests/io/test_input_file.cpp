// The one check before any reader opens a user's input file (core/input_file.hpp): a regular
// file that exists, can be read and is not larger than its reader's bound; a FIFO, a device or
// a directory is refused before it is opened, in one line naming the file.

#include "ceilplan/core/input_file.hpp"

#include "input_error.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace ceilplan {
namespace {

namespace fs = std::filesystem;

std::string refusal(const fs::path& file, std::uintmax_t max_bytes = kMaxInputFileBytes) {
  return testing::inputErrorOf([&] { requireInputFile(file, "map file", max_bytes); });
}

TEST(InputFile, RefusesWhatIsNotARegularReadableFileOfBoundedSize) {
  const fs::path dir = testing::scratchDirectory("input_file");
  std::ofstream(dir / "map.bt", std::ios::binary) << "12345";
  ASSERT_EQ(::mkfifo((dir / "pipe.bt").c_str(), 0600), 0);
  fs::create_symlink(dir / "map.bt", dir / "link.bt");
  // A FIFO would block the reader that opens it: the test dies rather than hangs.
  ::alarm(60);
  const struct {
    fs::path file;
    std::uintmax_t max_bytes;
    std::string says;
  } rows[] = {
      {dir / "none.bt", kMaxInputFileBytes, (dir / "none.bt").string() + ": no such map file"},
      {dir / "none" / "x.bt", kMaxInputFileBytes, (dir / "none" / "x.bt").string() + ": no such map file"},
      {dir, kMaxInputFileBytes, dir.string() + ": is a directory, not a map file; give a regular file"},
      {dir / "pipe.bt", kMaxInputFileBytes,
       (dir / "pipe.bt").string() + ": is a FIFO (named pipe), not a map file; give a regular file"},
      {"/dev/zero", kMaxInputFileBytes, "/dev/zero: is a device, not a map file; give a regular file"},
      {dir / "map.bt", 4,
       (dir / "map.bt").string() +
           ": holds 5 bytes, more than ceilplan reads for a map file (4); is it the right file?"},
  };
  for (const auto& row : rows) EXPECT_EQ(refusal(row.file, row.max_bytes), row.says) << row.file;
  ::alarm(0);

  EXPECT_EQ(requireInputFile(dir / "map.bt", "map file", 5), 5u);
  EXPECT_EQ(readInputFile(dir / "link.bt", "map file"), "12345");  // a link to a regular file is that file
  EXPECT_EQ(readInputFile(dir / "map.bt", "map file", 5), "12345");
}

TEST(InputFile, AnUnreadableFileSaysWhy) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads any file";
  const fs::path dir = testing::scratchDirectory("input_file_unreadable");
  std::ofstream(dir / "secret.bt") << "x";
  fs::permissions(dir / "secret.bt", fs::perms::none);
  EXPECT_EQ(refusal(dir / "secret.bt"), (dir / "secret.bt").string() + ": cannot be read: Permission denied");
}

}  // namespace
}  // namespace ceilplan
