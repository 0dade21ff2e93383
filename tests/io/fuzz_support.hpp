#pragma once
// Shared by the io libFuzzer targets: the readers take a path, so each input is written to a file
// in a private working directory (on /dev/shm when there is one), beside the files a mission
// names: every shipped map name (empty files: the mission reader checks that they exist) and the
// shipped vehicle, reachable as a mission in maps/ or maps/coverage/ names them.

#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace ceilplan::fuzzing {

inline std::filesystem::path workingDirectory() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path base = std::filesystem::exists("/dev/shm") ? "/dev/shm" : "/tmp";
    std::string name = (base / "ceilplan_fuzz_XXXXXX").string();
    if (::mkdtemp(name.data()) == nullptr) std::abort();
    const std::filesystem::path root(name);
    for (const std::filesystem::path& level : {root, root / "in"}) {
      std::filesystem::create_directories(level / "vehicles");
      std::filesystem::copy_file(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/vehicles/quad.yaml",
                                 level / "vehicles/quad.yaml");
      for (const char* map : {"bridge.bt", "open.bt", "tunnel.bt", "warehouse.bt"}) std::ofstream(level / map);
    }
    return root / "in";
  }();
  return dir;
}

// Writes the input to `name` in the working directory and returns its path.
inline std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size, const char* name) {
  const std::filesystem::path path = workingDirectory() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace ceilplan::fuzzing
