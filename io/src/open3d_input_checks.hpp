#pragma once
// Open3D 0.16's PCD and PLY readers trust what a file says about itself: a header's counts and
// offsets, a face's corners. A bad file makes them read out of bounds, crash, allocate gigabytes
// or return uninitialised points. These checks run before them and refuse such files with
// ceilplan::InputError: "FILE: not a readable KIND (the problem)", KIND "point cloud" or "mesh" as
// for a file Open3D refuses. Private to the io module.

#include <filesystem>
#include <string>

namespace ceilplan::io::detail {

// A PCD v0.7 header as PCL writes it (FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, POINTS, DATA; no
// other line but comments), and as many points after it as it announces.
void checkPcdFile(const std::filesystem::path& file);  // a point cloud

// A PLY header rply reads the same way, and a body holding every element it announces; each face
// of the mesh has at least three corners, each a vertex that exists.
void checkPlyFile(const std::filesystem::path& file, const std::string& kind);

}  // namespace ceilplan::io::detail
