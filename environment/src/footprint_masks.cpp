#include "ceilplan/environment/footprint_masks.hpp"

#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::environment {

FootprintMasks::FootprintMasks(const DistanceField& field, double footprint_radius_m, int workers)
    : frame_(field.frame()), unknown_blocks_(field.unknownIsBlocked()) {
  const int nx = frame_.size()[0], ny = frame_.size()[1], nz = frame_.size()[2];
  words_ = (nz + 63) / 64;
  const std::size_t layer = static_cast<std::size_t>(nx) * ny;
  // Within radius + sqrt(2) voxels of a column's centre: every column the cylinder can touch
  // from a body centre anywhere in that column (half a diagonal to the body, half to the square).
  const double reach = footprint_radius_m / frame_.resolution_m() + std::sqrt(2.0);
  // Squared distances between column centres are integers: compare with the largest one in
  // reach. Distances the field caps compare as "in reach" once the reach passes the cap:
  // conservative.
  const std::uint32_t reach_squared =
      static_cast<std::uint32_t>(std::min(std::floor(reach * reach), double(DistanceField::kHorizontalCap)));
  reach_.assign(layer * words_, 0);
  const std::size_t bands = std::min<std::size_t>(ny, std::size_t(std::max(1, workers)) * 16);
  parallelFor(bands, workers, [&](std::size_t band) {
    const std::size_t c0 = band * ny / bands * nx, c1 = (band + 1) * ny / bands * nx;
    for (int k = 0; k < nz; ++k) {
      const std::uint64_t bit = std::uint64_t{1} << (k % 64);
      const std::size_t voxel0 = static_cast<std::size_t>(k) * layer;
      for (std::size_t c = c0; c < c1; ++c)
        if (field.horizontalSquared(voxel0 + c) <= reach_squared) reach_[c * words_ + k / 64] |= bit;
    }
    if (!unknown_blocks_) return;
    // Outside the grid every voxel is unknown: a column within reach of the edge may meet it.
    for (std::size_t c = c0; c < c1; ++c) {
      const long i = static_cast<long>(c % nx), j = static_cast<long>(c / nx);
      const long edge = std::min({i + 1, nx - i, j + 1, ny - j});
      if (static_cast<double>(edge * edge) <= reach * reach)
        std::fill_n(reach_.data() + c * words_, words_, ~std::uint64_t{0});
    }
  });
}

bool FootprintMasks::mayBlock(int i, int j, double bottom_m, double top_m) const {
  // The voxels holding the interval's ends are included even when only touched: conservative.
  const int nz = frame_.size()[2];
  int k_lo = frame_.indexOf(2, bottom_m), k_hi = frame_.indexOf(2, top_m);
  if (k_lo < 0 || k_hi >= nz) {
    if (unknown_blocks_) return true;  // above and below the grid every voxel is unknown
    k_lo = std::max(k_lo, 0);
    k_hi = std::min(k_hi, nz - 1);
    if (k_lo > k_hi) return false;
  }
  const std::uint64_t* bits = reach_.data() + (static_cast<std::size_t>(j) * frame_.size()[0] + i) * words_;
  for (int w = k_lo / 64; w <= k_hi / 64; ++w) {
    const int lo = std::max(k_lo - 64 * w, 0), hi = std::min(k_hi - 64 * w, 63);
    const std::uint64_t range =
        (hi == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (hi + 1)) - 1) & ~((std::uint64_t{1} << lo) - 1);
    if (bits[w] & range) return true;
  }
  return false;
}

}  // namespace ceilplan::environment
