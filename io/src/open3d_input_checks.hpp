#pragma once
// Open3D 0.16's PCD and PLY readers trust what a file says about itself: a header's counts and
// offsets, a face's corners. A bad file makes them read out of bounds, crash, allocate gigabytes
// or return uninitialised points. These checks run before them and refuse such files, each with
// one line that names the file and the problem (ceilplan::InputError). Private to the io module.

#include <filesystem>

namespace ceilplan::io::detail {

// A PCD v0.7 header as PCL writes it (FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, POINTS, DATA; no
// other line but comments), and as many points after it as it announces.
void checkPcdFile(const std::filesystem::path& file);

// A PLY header rply reads the same way, and a body holding every element it announces; each face
// of the mesh has at least three corners, each a vertex that exists.
void checkPlyFile(const std::filesystem::path& file);

}  // namespace ceilplan::io::detail
