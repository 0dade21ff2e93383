// libFuzzer target: any bytes given as a `--config` file (io::readFlagFile) give flag entries or a
// ceilplan::Error, never a crash, a hang, a leak or another exception; every entry names a flag
// the command takes. Build and run: scripts/fuzz-flag-file.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/flag_file.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Some of `ceilplan tour`'s flags; a section named "tour" holds flags too.
  static const std::vector<std::string> flags{"mission", "out",  "mode",      "seed",  "planner",
                                              "workers", "days", "no-export", "config"};
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    for (const ceilplan::io::FlagFileEntry& entry : ceilplan::io::readFlagFile(in, flags, "tour"))
      if (std::find(flags.begin(), flags.end(), entry.flag) == flags.end()) std::abort();
  } catch (const ceilplan::Error&) {
  }
  return 0;
}
