// Plans one route through a map with the built-in vehicle and checks it again, densely.
//   plan_route MAP.bt X0 Y0 Z0 X1 Y1 Z1   (e.g. share/ceilplan/maps/bridge.bt -4 0 0.5 10 0 5.5)
#include <ceilplan/ceilplan.hpp>

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 8) {
    std::cerr << "usage: plan_route MAP.bt X0 Y0 Z0 X1 Y1 Z1\n";
    return 2;
  }
  using namespace ceilplan;
  try {
    const mission::PlanningContext context(environment::OccupancyMap::load(argv[1]), mission::Vehicle::defaultQuad(),
                                           mission::BatterySpec{}, mission::PlanningOptions{});
    planner::PlanRequest request;
    request.start_m = {std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4])};
    request.goal_m = {std::atof(argv[5]), std::atof(argv[6]), std::atof(argv[7])};
    request.time_limit_s = 2.0;  // BIT*, the default planner, then refinement
    const mission::RoutePlan route = mission::planRoute(context, mission::FlightMode::Ceiling, request);
    const mission::RouteCheck check = mission::checkRoute(context, route.plan.waypoints);
    std::cout << route.plan.waypoints.size() << " waypoints, " << io::figuresLine(check.evaluation) << '\n'
              << (check.violation ? "UNSAFE: " + *check.violation : std::string("passes the dense re-check")) << '\n';
    return check.violation ? 1 : 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
}
