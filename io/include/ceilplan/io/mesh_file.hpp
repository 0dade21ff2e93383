#pragma once
/// @file
/// Mesh files, read with assimp (docs/import.md says why that library).

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/map_builder.hpp"

#include <filesystem>
#include <string>

namespace ceilplan::io {

/// The extensions readTriangleMesh accepts, e.g. ".stl, .obj, ...", for messages and help.
std::string meshExtensions();

/// The vertices and triangles of an .stl (ascii or binary), .obj, .ply, .off, .gltf, .glb, .dae or
/// .fbx file, in metres with z up (glTF, COLLADA and FBX turned from the axes they state), node
/// transforms applied; polygon faces of any size are split into triangles. Throws
/// ceilplan::InputError naming the file: missing, a point-cloud or other wrong-kind extension,
/// unreadable or corrupt, no triangle, only zero-area triangles, or coordinates too far from
/// the origin for the single precision its format is read in (not .ply and .off).
environment::TriangleMesh readTriangleMesh(const std::filesystem::path& file);

}  // namespace ceilplan::io
