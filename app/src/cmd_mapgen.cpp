// `ceilplan mapgen`: writes one of the shipped inspection scenes as an OctoMap file.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/scenes.hpp"
#include "ceilplan/io/octomap_file.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/report_text.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace ceilplan::app {
namespace {

struct MapgenOptions {
  std::string scene;
  std::string out;
  environment::SceneOptions scene_options;
};

void runMapgen(const MapgenOptions& options) {
  using namespace environment;
  const Scene scene = sceneFromName(options.scene);
  const std::filesystem::path out(options.out);
  if (!io::isOctoMapFileName(out))
    throw ceilplan::InputError("--out " + options.out + ": the map file must end in .bt (or .ot)");
  io::OutputSet outputs({{"--out", out}}, commandInputs({}));
  const VoxelGrid grid = generateScene(scene, options.scene_options);
  const std::unique_ptr<octomap::OcTree> tree = toOcTree(grid);
  io::writeOctoMapFile(outputs.path("--out"), *tree);
  outputs.commit();
  print(io::generatedSceneLine(options.scene, options.scene_options, grid, tree->size(), out));
}

const CommandRegistration registration(20, [](CLI::App& parent) {
  auto options = std::make_shared<MapgenOptions>();
  CLI::App* command = parent.add_subcommand("mapgen", "Generate a shipped inspection scene as an OctoMap (.bt)");
  command->add_option("--scene", options->scene, "bridge, tunnel, warehouse or open")->required();
  command->add_option("--out", options->out, "Output file (.bt, or .ot for OctoMap's full format)")->required();
  command->add_option("--resolution", options->scene_options.resolution_m, "Voxel size in metres (0.02 to 1)")
      ->capture_default_str();
  command->add_option("--seed", options->scene_options.seed, "Seed placing the scene's clutter")
      ->capture_default_str()
      ->check(wholeNumber());
  command
      ->add_option("--bridge-length-m", options->scene_options.bridge_length_m,
                   "Bridge only: span between the abutments, a multiple of 4 m from 16 to 2000 (piers every 16 m)")
      ->capture_default_str();
  command->callback([options] { runMapgen(*options); });
});

}  // namespace
}  // namespace ceilplan::app
