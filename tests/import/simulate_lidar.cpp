// simulate_lidar: a terrestrial LiDAR survey of an OctoMap scene, for import tests, the
// benchmark figure and docs/import.md, where no public scan of a bridge can be shipped. From
// each station a spinning scanner casts rays on a regular azimuth x elevation grid; a ray that
// hits an occupied voxel returns the point where it enters that voxel, moved along the ray by
// Gaussian range noise. Writes a PCD (binary, or ascii with --offset) and an origins CSV (first_point,x,y,z per
// station).
//
//   simulate_lidar --map maps/bridge.bt --stations "4,0,2;20,0,2" --out scan.pcd --origins scan_origins.csv
//                  [--azimuth-steps 1440] [--elevation-steps 360] [--max-range 60] [--noise 0.005]
//                  [--offset E,N,Z] [--seed 1]

#include "scan_files.hpp"

#include "ceilplan/environment/occupancy_map.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

namespace {

std::vector<Eigen::Vector3d> parsePoints(const std::string& text) {
  std::vector<Eigen::Vector3d> points;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ';')) {
    Eigen::Vector3d p;
    if (std::sscanf(item.c_str(), "%lf,%lf,%lf", &p.x(), &p.y(), &p.z()) != 3)
      throw std::runtime_error("bad point '" + item + "'");
    points.push_back(p);
  }
  return points;
}

// Where the ray origin + t direction enters the voxel box [lo, hi] (slab method).
Eigen::Vector3d entryPoint(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Eigen::Vector3d& lo,
                           const Eigen::Vector3d& hi) {
  double enter = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(direction[axis]) < 1e-12) continue;
    const double t0 = (lo[axis] - origin[axis]) / direction[axis], t1 = (hi[axis] - origin[axis]) / direction[axis];
    enter = std::max(enter, std::min(t0, t1));
  }
  return origin + enter * direction;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Simulated terrestrial LiDAR survey of an OctoMap scene"};
  std::string map_file, stations_text, out, origins_out, offset_text = "0,0,0";
  int azimuth_steps = 1440, elevation_steps = 360;
  double max_range = 60.0, noise = 0.005;
  unsigned seed = 1;
  app.add_option("--map", map_file)->required();
  app.add_option("--stations", stations_text, "x,y,z;x,y,z;... in the map frame")->required();
  app.add_option("--out", out, "Point cloud (.pcd, binary)")->required();
  app.add_option("--origins", origins_out, "Origins CSV (first_point,x,y,z)")->required();
  app.add_option("--azimuth-steps", azimuth_steps);
  app.add_option("--elevation-steps", elevation_steps, "Between -60 and +90 degrees");
  app.add_option("--max-range", max_range);
  app.add_option("--noise", noise, "Range noise, standard deviation in metres");
  app.add_option("--offset", offset_text, "Added to every point and origin, e.g. projected coordinates E,N,Z");
  app.add_option("--seed", seed);
  CLI11_PARSE(app, argc, argv);

  try {
    const auto map = ceilplan::environment::OccupancyMap::load(map_file);
    const octomap::OcTree& tree = map.tree();
    const double resolution = tree.getResolution();
    const Eigen::Vector3d offset = parsePoints(offset_text).at(0);
    std::mt19937_64 random(seed);
    std::normal_distribution<double> range_noise(0.0, noise);
    std::vector<Eigen::Vector3d> points;
    std::ofstream origins(origins_out);
    origins.precision(12);
    origins << "first_point,x,y,z\n";
    for (const Eigen::Vector3d& station : parsePoints(stations_text)) {
      const Eigen::Vector3d placed = station + offset;
      origins << points.size() << ',' << placed.x() << ',' << placed.y() << ',' << placed.z() << '\n';
      const octomap::point3d from(float(station.x()), float(station.y()), float(station.z()));
      for (int e = 0; e < elevation_steps; ++e) {
        const double elevation = (-60.0 + 150.0 * (e + 0.5) / elevation_steps) * M_PI / 180.0;
        for (int a = 0; a < azimuth_steps; ++a) {
          const double azimuth = 2.0 * M_PI * (a + 0.5) / azimuth_steps;
          const Eigen::Vector3d direction(std::cos(elevation) * std::cos(azimuth),
                                          std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
          octomap::point3d end;
          if (!tree.castRay(from, octomap::point3d(float(direction.x()), float(direction.y()), float(direction.z())),
                            end,
                            /*ignoreUnknown=*/true, max_range))
            continue;
          const Eigen::Vector3d centre(end.x(), end.y(), end.z());
          const Eigen::Vector3d hit =
              entryPoint(station, direction, centre.array() - 0.5 * resolution, centre.array() + 0.5 * resolution);
          points.push_back(hit + range_noise(random) * direction + offset);
        }
      }
    }
    // Projected coordinates need doubles; binary PCD of doubles is not readable by Open3D 0.16.
    ceilplan::testing::writePcd(out, points, /*binary=*/offset.isZero());
    std::printf("%zu points from %zu stations -> %s, %s\n", points.size(), parsePoints(stations_text).size(),
                out.c_str(), origins_out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simulate_lidar: %s\n", e.what());
    return 1;
  }
  return 0;
}
