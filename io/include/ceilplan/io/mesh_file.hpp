#pragma once
// Triangle-mesh files, read with Open3D (docs/import.md says why that library).

#include "ceilplan/environment/map_builder.hpp"
#include "ceilplan/core/error.hpp"

#include <filesystem>
#include <string>

namespace ceilplan::io {

// The extensions readTriangleMesh accepts, e.g. ".stl, .obj, ...", for messages and help.
std::string meshExtensions();

// The vertices and triangles of an .stl (ascii or binary), .obj, .ply or .off file (faces with
// more corners are split into triangles). Throws ceilplan::InputError naming the file:
// missing, a point-cloud or other wrong-kind extension, unreadable or corrupt, or no triangle.
environment::TriangleMesh readTriangleMesh(const std::filesystem::path& file);

}  // namespace ceilplan::io
