// libFuzzer target: any bytes given as a vehicle file or a battery file give a vehicle (with a
// valid energy model) or a battery, or a ceilplan::InputError; never a crash, a hang, a leak or
// another exception. Build and run: scripts/fuzz-vehicle-yaml (docs/missions.md).

#include "fuzz_support.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/vehicle_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = ceilplan::fuzzing::inputFile(data, size, "vehicle.yaml");
  try {
    const ceilplan::mission::Vehicle vehicle = ceilplan::io::readVehicle(file);
    // What the reader accepts, the energy model must take, or refuse in words (a pack that
    // cannot lift the vehicle is a runtime failure, ceilplan::Error).
    try {
      const ceilplan::energy::EnergyModel model(vehicle.energy);
      model.currentA(ceilplan::energy::kNoSurface, 0.0, ceilplan::energy::FlightCondition{});
    } catch (const ceilplan::Error&) {
    }
  } catch (const ceilplan::InputError&) {
  }
  try {
    ceilplan::io::readBattery(file);
  } catch (const ceilplan::InputError&) {
  }
  return 0;
}
