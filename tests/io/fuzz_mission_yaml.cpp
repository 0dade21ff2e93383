// libFuzzer target: any bytes given as a mission file (or as a battery file, which may be a
// mission file) give a mission or a ceilplan::InputError, never a crash, a hang, a leak or another
// exception. Build and run: scripts/fuzz-mission-yaml (docs/missions.md).

#include "fuzz_support.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/mission_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = ceilplan::fuzzing::inputFile(data, size, "mission.yaml");
  try {
    ceilplan::io::readMission(file);
  } catch (const ceilplan::InputError&) {
  }
  try {
    ceilplan::io::readBattery(file);
  } catch (const ceilplan::InputError&) {
  }
  return 0;
}
