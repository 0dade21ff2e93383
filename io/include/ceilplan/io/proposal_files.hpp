#pragma once
/// @file
/// The files of `ceilplan propose` (docs/import.md, "A mission from the map"): the proposed
/// coverage mission as a mission file, a plan-view picture of its regions and home, and the
/// summary lines.

#include "ceilplan/core/progress.hpp"
#include "ceilplan/environment/unknown_space.hpp"
#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/mission/mission_proposal.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

/// What the proposed mission says besides the proposal: each has a default the user may change
/// (with the command's flags, or in the file afterwards).
struct ProposalSettings {
  std::filesystem::path map_file;                  ///< written relative to the mission file's directory
  std::filesystem::path vehicle_file;              ///< the same
  std::string camera_preset = "zenmuse_h20_wide";  ///< the camera (mission::cameraPresets())
  double gsd_mm_px = 2.0;                          ///< required GSD of each region
  double overlap_front_pct = 70.0;                 ///< front overlap of each region
  double overlap_side_pct = 60.0;                  ///< side overlap of each region
  double max_incidence_deg = 45.0;                 ///< largest incidence of each region
  std::uint32_t seed = 1;                          ///< the mission's seed
  /// The policy the home was checked under: the mission's `unknown:` key, so that its tours assume
  /// the same (written only when not the default, occupied).
  environment::UnknownSpace unknown;

  /// Throws ceilplan::InputError naming the setting, with the ranges a mission file allows
  /// (mission::CoverageRegion::validate, the camera presets).
  void validate() const;
};

/// `ceilplan propose` and `ceilplan.propose` in one: what to read, propose and write.
struct ProposalRequest {
  std::filesystem::path mission_file;  ///< .yaml or .yml
  std::filesystem::path picture_file;  ///< .svg; empty: beside the mission file
  mission::ProposalOptions options;    ///< how regions and the home are proposed
  ProposalSettings settings;           ///< with the map and vehicle files to read
  /// How messages name the two outputs ("--out", "--picture" for the command line).
  std::string mission_flag = "mission file", picture_flag = "picture";
  /** @var picture_flag
   *  How messages name the picture output. */
  std::vector<Input> other_inputs;  ///< besides the map and the vehicle (a --config file)
};

/// Checks the request and the outputs (io::OutputSet, before any work), indexes the map for the
/// vehicle under settings.unknown, proposes, and writes the mission file and the picture as one
/// output set. Sets `picture_file` when it was empty. The mission file's provenance is
/// `provenance` with the map and the vehicle added.
mission::MissionProposal proposeMissionFiles(ProposalRequest& request, Provenance provenance,
                                             const ProgressCallback& progress = {});

/// The mission file's text: map, vehicle, a default battery, home, speeds, seed, the camera on an
/// upward mount and one `surfaces:` entry per region (faces [down]); no `origin:` (a scan has
/// none: the tour writes its local-frame outputs). `mission_file` is where it will be read from;
/// `provenance` goes in its first comment line.
std::string proposedMissionYaml(const mission::MissionProposal& proposal, const ProposalSettings& settings,
                                const std::filesystem::path& mission_file, const Provenance& provenance);

/// A plan view (SVG): what stands below the regions shaded by height, the regions outlined and
/// named, the home marked, a scale bar; `title` names the map.
std::string proposalPictureSvg(const environment::VoxelGrid& grid, const mission::MissionProposal& proposal,
                               const std::string& title);

/// The summary: one line per region, the home, what was dropped, and the files written.
std::string proposalText(const mission::MissionProposal& proposal, const std::filesystem::path& mission_file,
                         const std::filesystem::path& picture_file);

}  // namespace ceilplan::io
