// `ceilplan propose`: a coverage mission from the map alone: its overhead surfaces as regions,
// a home, and a picture of both (docs/import.md, "A mission from the map").

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "map_options.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/io/point_text.hpp"
#include "ceilplan/io/proposal_files.hpp"
#include "ceilplan/mission/mission_proposal.hpp"

#include <memory>
#include <string>

namespace ceilplan::app {
namespace {

struct ProposeArguments {
  std::string map, vehicle, out, picture, home, crop;
  mission::ProposalOptions options;
  io::ProposalSettings settings;
  UnknownSpaceFlags unknown;
};

void runPropose(ProposeArguments a) {
  io::ProposalRequest request;
  request.mission_file = a.out;
  request.picture_file = a.picture;
  request.mission_flag = "--out";
  request.picture_flag = "--picture";
  request.other_inputs = commandInputs({});
  if (!a.home.empty()) a.options.home_m = parsePoint(a.home, "--home");
  if (!a.crop.empty()) {
    try {
      a.options.crop_m = io::parseBox(a.crop);
    } catch (const InputError&) {
      rethrowWithContext("--crop ");
    }
  }
  request.options = a.options;
  request.settings = a.settings;
  request.settings.map_file = a.map;
  request.settings.vehicle_file = a.vehicle;
  request.settings.unknown = a.unknown.value();
  const mission::MissionProposal proposal = io::proposeMissionFiles(request, commandProvenance(), terminalProgress());
  print(io::proposalText(proposal, request.mission_file, request.picture_file));
}

const CommandRegistration registration(23, [](CLI::App& parent) {
  auto a = std::make_shared<ProposeArguments>();
  CLI::App* command = parent.add_subcommand(
      "propose", "Propose a coverage mission from a map: its overhead surfaces, a home, and a picture (" +
                     docPage("import.md") + ")");
  command->add_option("--map", a->map, "OctoMap file (.bt or .ot), e.g. from ceilplan import")->required();
  command->add_option("--vehicle", a->vehicle, "Vehicle file the mission flies (e.g. maps/vehicles/quad.yaml)")
      ->required();
  command->add_option("--out", a->out, "The mission file to write (.yaml)")->required();
  command->add_option("--picture", a->picture, "Plan view of the regions and the home (.svg; default: beside --out)");
  command->add_option("--home", a->home, "Take-off position x,y,z in metres (default: proposed)");
  command->add_option("--crop", a->crop, "Only surfaces in this box: xmin,ymin,zmin,xmax,ymax,zmax in metres");
  command->add_option("--min-area-m2", a->options.min_region_area_m2, "Drop overhead regions of less area")
      ->check(nonNegativeFinite())
      ->capture_default_str();
  command->add_option("--max-regions", a->options.max_regions, "At most this many regions, the largest first")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  command
      ->add_option("--camera", a->settings.camera_preset,
                   "Camera preset (" + docPage("coverage.md") + "), on an upward mount")
      ->capture_default_str();
  command->add_option("--gsd-mm-px", a->settings.gsd_mm_px, "Required ground sample distance")
      ->check(finiteRange(1e-3, 1000.0))
      ->capture_default_str();
  command->add_option("--overlap-front", a->settings.overlap_front_pct, "Forward overlap of the photos, %")
      ->check(finiteRange(0.0, 99.0))
      ->capture_default_str();
  command->add_option("--overlap-side", a->settings.overlap_side_pct, "Side overlap of the photos, %")
      ->check(finiteRange(0.0, 99.0))
      ->capture_default_str();
  command->add_option("--seed", a->settings.seed, "The mission's seed (of every random choice of its tours)")
      ->check(CLI::Range(1u, 4294967295u))
      ->capture_default_str();
  a->unknown.addTo(*command);
  command->callback([a] { runPropose(*a); });
});

}  // namespace
}  // namespace ceilplan::app
