#include "ceilplan/environment/surface_elements.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ceilplan::environment {
namespace {

constexpr int kFaceCount = 6;
constexpr int kNeighbourhoodVoxels = 2;  // Chebyshev radius of the normal estimate
// Largest RMS distance (voxels) of the faces around an element from one inclined plane for them to
// count as its staircase: steps of any length deviate by at most 0.29 (a uniform spread over
// +-0.5 voxel), an L of faces by about a voxel.
constexpr double kStaircaseRmsVoxels = 0.35;

// Axis and direction of face `face`: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z.
int axisOf(int face) { return face / 2; }
int signOf(int face) { return face % 2 == 0 ? 1 : -1; }

bool exposed(const VoxelGrid& grid, int i, int j, int k, int face) {
  if (grid.at(i, j, k) != CellState::Occupied) return false;
  Index3 across{i, j, k};
  across[axisOf(face)] += signOf(face);
  return grid.at(across[0], across[1], across[2]) == CellState::Free;
}

// Which faces of each voxel in a box of the grid are exposed (bit f for face f), so that the
// normal estimate reads one byte per neighbour.
class ExposureMask {
 public:
  ExposureMask(const VoxelGrid& grid, const Index3& lo, const Index3& hi) : lo_(lo) {
    for (int axis = 0; axis < 3; ++axis) size_[axis] = hi[axis] - lo[axis] + 1;
    bits_.assign(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2], 0);
    for (int k = 0; k < size_[2]; ++k)
      for (int j = 0; j < size_[1]; ++j)
        for (int i = 0; i < size_[0]; ++i) {
          std::uint8_t bits = 0;
          for (int face = 0; face < kFaceCount; ++face)
            if (exposed(grid, lo[0] + i, lo[1] + j, lo[2] + k, face)) bits |= static_cast<std::uint8_t>(1u << face);
          bits_[linear(i, j, k)] = bits;
        }
  }

  // Exposed faces of voxel (i, j, k), grid indices; none outside the box.
  std::uint8_t at(int i, int j, int k) const {
    i -= lo_[0];
    j -= lo_[1];
    k -= lo_[2];
    if (i < 0 || j < 0 || k < 0 || i >= size_[0] || j >= size_[1] || k >= size_[2]) return 0;
    return bits_[linear(i, j, k)];
  }

 private:
  std::size_t linear(int i, int j, int k) const { return (static_cast<std::size_t>(k) * size_[1] + j) * size_[0] + i; }

  Index3 lo_;
  Index3 size_{};
  std::vector<std::uint8_t> bits_;
};

// The local surface's normal at an exposed face (see the header). Face centres and normals are
// taken in voxel units relative to the face's voxel centre.
Eigen::Vector3d localNormal(const ExposureMask& mask, const Index3& voxel, int face) {
  const Eigen::Vector3d own = faceAxisNormal(face);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> centres;
  bool flat = true;
  for (int dk = -kNeighbourhoodVoxels; dk <= kNeighbourhoodVoxels; ++dk)
    for (int dj = -kNeighbourhoodVoxels; dj <= kNeighbourhoodVoxels; ++dj)
      for (int di = -kNeighbourhoodVoxels; di <= kNeighbourhoodVoxels; ++di) {
        const std::uint8_t bits = mask.at(voxel[0] + di, voxel[1] + dj, voxel[2] + dk);
        if (bits == 0) continue;
        for (int f = 0; f < kFaceCount; ++f) {
          if (!(bits & (1u << f))) continue;
          const Eigen::Vector3d n = faceAxisNormal(f);
          if (n.dot(own) < 0.0) continue;
          const Eigen::Vector3d centre = Eigen::Vector3d(di, dj, dk) + 0.5 * n;
          flat = flat && f == face && centre.dot(own) == 0.5;
          sum += n;
          centres.push_back(centre);
        }
      }
  if (flat) return own;
  // A staircase following an inclined plane has every face centre within about 0.3 voxel of
  // that plane, whose normal is the sum of the faces' normals; an edge or corner of a box (an L
  // of faces) is far from any single plane and keeps its axis normal.
  const Eigen::Vector3d inclined = sum.normalized();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& c : centres) centroid += c;
  centroid /= static_cast<double>(centres.size());
  double squares = 0.0;
  for (const Eigen::Vector3d& c : centres) squares += std::pow((c - centroid).dot(inclined), 2);
  return std::sqrt(squares / static_cast<double>(centres.size())) <= kStaircaseRmsVoxels ? inclined : own;
}

}  // namespace

Eigen::Vector3d faceAxisNormal(int face) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  normal[axisOf(face)] = signOf(face);
  return normal;
}

Eigen::Vector3d SurfaceElement::faceNormal() const { return faceAxisNormal(face); }

std::vector<SurfaceElement> exposedSurface(const VoxelGrid& grid, const Eigen::AlignedBox3d& box_m) {
  const GridFrame& frame = grid.frame();
  const double r = frame.resolution_m();
  std::vector<SurfaceElement> elements;
  if (box_m.isEmpty()) return elements;
  // Voxels whose faces can lie in the box: one voxel beyond it on every side, clipped to the grid.
  Index3 lo, hi;
  for (int axis = 0; axis < 3; ++axis) {
    lo[axis] = std::max(0, frame.indexOf(axis, box_m.min()[axis]) - 1);
    hi[axis] = std::min(frame.size()[axis] - 1, frame.indexOf(axis, box_m.max()[axis]) + 1);
  }
  Index3 mask_lo, mask_hi;
  for (int axis = 0; axis < 3; ++axis) {
    mask_lo[axis] = lo[axis] - kNeighbourhoodVoxels;
    mask_hi[axis] = hi[axis] + kNeighbourhoodVoxels;
  }
  const ExposureMask mask(grid, mask_lo, mask_hi);
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::uint8_t bits = mask.at(i, j, k);
        if (bits == 0) continue;
        const Index3 voxel{i, j, k};
        for (int face = 0; face < kFaceCount; ++face) {
          if (!(bits & (1u << face))) continue;
          SurfaceElement element;
          element.voxel = voxel;
          element.face = face;
          for (int axis = 0; axis < 3; ++axis) element.centre_m[axis] = frame.centreOf(axis, voxel[axis]);
          element.centre_m[axisOf(face)] += 0.5 * r * signOf(face);
          if (!box_m.contains(element.centre_m)) continue;
          element.normal = localNormal(mask, voxel, face);
          element.area_m2 = r * r * std::abs(element.normal.dot(faceAxisNormal(face)));
          elements.push_back(element);
        }
      }
  return elements;
}

}  // namespace ceilplan::environment
