#pragma once
/// @file
/// A horizontal slice through a map's index as CSV (`ceilplan mapinfo --slice-csv`,
/// docs/environment.md): what the map holds in each column at one height, what the
/// unknown-space policy assumed there, and whether a vehicle's body centre may be there.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/io/provenance.hpp"

#include <filesystem>
#include <string>

namespace ceilplan::io {

/// The provenance comment line, then one row per column of the index's grid at height `z_m`: x_m, y_m, state (occupied,
/// free, unknown, assumed_free), under_ceiling (environment::ceilingColumns), and with `environment` (a vehicle on the
/// same index) valid and assumes_free. Written atomically. Throws ceilplan::InputError, before writing, for a height
/// outside the map ("`height_name` Z lies outside the map, whose heights span ...").
void writeMapSliceCsv(const std::filesystem::path& file, const environment::MapIndex& index, double z_m,
                      const environment::Environment* environment, const std::string& height_name,
                      const Provenance& provenance);

}  // namespace ceilplan::io
