#pragma once
// Open3D 0.16's PCD, PLY and XYZ readers trust what a file says about itself: a
// header's counts and offsets, a face's corners. A bad file makes them read out
// of bounds, crash, allocate gigabytes, return uninitialised points, or skip
// data without a word. These checks run before them and refuse such files with
// ceilplan::InputError: "FILE: not a readable KIND (the problem)", KIND "point
// cloud" or "mesh" as for a file Open3D refuses. Private to the io module.

#include <cstddef>
#include <filesystem>
#include <string>

namespace ceilplan::io::detail {

// A PCD v0.7 header as PCL writes it (FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT,
// POINTS, DATA; no other line but comments), WIDTH x HEIGHT = POINTS, and as
// many points after it as it announces: in an ascii PCD, exactly POINTS rows,
// each with a point's values.
void checkPcdFile(const std::filesystem::path& file);  // a point cloud

// A PLY header rply reads the same way, and a body holding every element it
// announces; each face of the mesh has at least three corners, each a vertex
// that exists; no data after them.
void checkPlyFile(const std::filesystem::path& file, const std::string& kind);

// Every non-blank line of an .xyz (3) or .xyzn/.xyzrgb (6) file starts with
// that many numbers (what follows them is ignored, as Open3D does; Open3D skips
// any other line without a word).
void checkXyzFile(const std::filesystem::path& file, std::size_t numbers_per_line);

}  // namespace ceilplan::io::detail
