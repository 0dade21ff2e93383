// Plans a mission's inspection tour in ceiling mode and in free mode, prints the comparison and
// writes each mode's QGroundControl .plan files.
//   tour_both_modes MISSION.yaml OUT_DIR     (e.g. share/ceilplan/maps/bridge.yaml)
#include <ceilplan/ceilplan.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: tour_both_modes MISSION.yaml OUT_DIR\n";
    return 2;
  }
  using namespace ceilplan;
  try {
    const mission::Mission mission = io::readMission(argv[1]);
    const mission::PlanningContext context(mission);  // loads and indexes the map once
    const mission::TourResult ceiling = mission::planTour(mission, context, mission::FlightMode::Ceiling);
    const mission::TourResult free = mission::planTour(mission, context, mission::FlightMode::Free);
    std::cout << io::comparisonTable(ceiling, free);
    for (const mission::TourResult* tour : {&ceiling, &free}) {
      const auto plans = io::autopilotMissions(*tour, mission, io::Autopilot::PX4);
      for (std::size_t k = 0; k < plans.size(); ++k) {
        const std::filesystem::path file =
            io::sortieFileName(std::filesystem::path(argv[2]) / (mission::flightModeName(tour->mode) + ".plan"),
                               int(k) + 1, int(plans.size()));
        io::writeQgcPlan(file, plans[k]);
        std::cout << "wrote " << file.string() << '\n';
      }
    }
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
}
