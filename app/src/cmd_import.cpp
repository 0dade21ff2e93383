// `ceilplan import`: an OctoMap (.bt) from a point cloud (with or without sensor origins) or a
// mesh, optionally moved from a projected CRS into a local frame (docs/import.md).

#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/io/map_import.hpp"
#include "ceilplan/io/mesh_file.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/point_cloud_file.hpp"
#include "ceilplan/io/point_text.hpp"
#include "ceilplan/io/report_text.hpp"

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

namespace ceilplan::app {
namespace {

struct ImportArguments {
  io::MapImportOptions options;
  std::string points, origins, mesh, out, crop;
};

void runImport(const ImportArguments& args) {
  io::MapImportOptions options = args.options;
  options.points = args.points;
  options.origins = args.origins;
  options.mesh = args.mesh;
  const std::filesystem::path out(args.out);
  if (out.extension() != ".bt") throw ceilplan::InputError("--out " + args.out + ": the map file must end in .bt");
  std::filesystem::path summary = out;
  summary += ".json";
  // Checked and staged before the cloud is read; the map and its summary appear together.
  io::OutputSet outputs({{"--out", out}, {"--out's summary", summary}},
                        commandInputs({{"--points", args.points}, {"--origins", args.origins}, {"--mesh", args.mesh}}));
  if (!(options.resolution_m >= environment::kMinImportResolution_m &&
        options.resolution_m <= environment::kMaxImportResolution_m))
    throw ceilplan::InputError("--resolution " + formatNumber(options.resolution_m) + ": use " +
                               formatNumber(environment::kMinImportResolution_m) + " to " +
                               formatNumber(environment::kMaxImportResolution_m) + " m");
  if (!std::isfinite(options.max_range_m) || options.max_range_m < 0.0)
    throw ceilplan::InputError("--max-range " + formatNumber(options.max_range_m) +
                               ": a finite number of metres >= 0 (0: none)");
  if (!args.crop.empty()) {
    try {
      options.crop_m = io::parseBox(args.crop);
    } catch (const ceilplan::InputError& e) {
      throw ceilplan::InputError(std::string("--crop ") + e.what());
    }
  }

  io::MapImport imported = [&] {
    const ProgressCallback progress = terminalProgress();  // cleared when the import ends
    return io::importMap(options, progress);
  }();
  // After the readers, whose messages say what is wrong with a file better than "cannot be read".
  const io::Provenance provenance =
      commandProvenance().input("points", args.points).input("origins", args.origins).input("mesh", args.mesh);
  io::writeImportedMap(outputs.path("--out"), imported, options, provenance, outputs.path("--out's summary"));
  outputs.commit();

  print(io::mapImportText(imported, options, out));
}

const CommandRegistration registration(19, [](CLI::App& parent) {
  auto args = std::make_shared<ImportArguments>();
  CLI::App* command = parent.add_subcommand(
      "import", "Build an OctoMap (.bt) from a point cloud or a mesh of your structure (" + docPage("import.md") + ")");
  CLI::Option_group* input = command->add_option_group("input", "What to import: one of");
  CLI::Option* points = input->add_option("--points", args->points, "Point cloud: " + io::pointCloudExtensions());
  input->add_option("--mesh", args->mesh, "Triangle mesh: " + io::meshExtensions());
  input->require_option(1);
  CLI::Option* origins = command->add_option("--origins", args->origins,
                                             "CSV of sensor positions (x,y,z per point or for all, or "
                                             "first_point,x,y,z per scan): free space is carved by ray casting");
  origins->needs(points);
  command->add_option("--resolution", args->options.resolution_m, "Voxel size in metres")->required();
  command->add_option("--out", args->out, "Output map (.bt); a summary goes beside it in <out>.json")->required();
  command->add_option(
      "--crs", args->options.crs,
      "EPSG code of the data's projected CRS (e.g. EPSG:25832): moves them into a local east-north-up frame "
      "and prints the geodetic origin for the mission file");
  command
      ->add_option("--max-range", args->options.max_range_m,
                   "With --origins: returns farther than this from their origin are dropped, their rays carve up to "
                   "it, in metres (0: no limit)")
      ->capture_default_str()
      ->needs(origins);
  command
      ->add_option("--free-distance", args->options.free_distance_m,
                   "Without --origins: space farther than this from every point is free (default: two voxels)")
      ->needs(points)
      ->excludes(origins);
  command
      ->add_option("--free-region", args->options.free_region,
                   "Without --origins: where that holds: between (only where a point lies above and below, in "
                   "the voxel's column: beyond the scanned surfaces stays unknown) or box (the whole box)")
      ->capture_default_str()
      ->needs(points)
      ->excludes(origins);
  command->add_option(
      "--margin", args->options.margin_m,
      "Known space beyond the data's bounding box, in metres (default: 1 for a mesh, 0 for a point cloud)");
  command->add_option("--crop", args->crop,
                      "XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX: a box in map coordinates (after --crs); data outside it are "
                      "dropped before voxelising and the map goes no farther");
  command
      ->add_option("--interior", args->options.interior,
                   "Mesh: what the surface encloses: auto (an open mesh is a thin shell, a closed one solid, or "
                   "hollow when it faces inward), solid, hollow or shell")
      ->capture_default_str();
  command->add_flag("--skip-non-finite", args->options.skip_non_finite,
                    "Drop points with NaN or infinite coordinates instead of refusing them");
  command->callback([args] { runImport(*args); });
});

}  // namespace
}  // namespace ceilplan::app
