#include "ceilplan/environment/footprint_masks.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::environment {

FootprintMasks::FootprintMasks(const VoxelGrid& grid, double footprint_radius_m, bool unknown_blocks)
    : frame_(grid.frame()), unknown_blocks_(unknown_blocks) {
  const int nx = frame_.size()[0], ny = frame_.size()[1], nz = frame_.size()[2];
  words_ = (nz + 63) / 64;
  const std::size_t columns = static_cast<std::size_t>(nx) * ny;
  // The blocking bits of each column, read in the grid's memory order (z outermost).
  std::vector<std::uint64_t> own(columns * words_, 0);
  for (int k = 0; k < nz; ++k)
    for (std::size_t c = 0; c < columns; ++c) {
      const CellState state = grid.atLinear(static_cast<std::size_t>(k) * columns + c);
      if (state == CellState::Occupied || (state == CellState::Unknown && unknown_blocks_))
        own[c * words_ + k / 64] |= std::uint64_t{1} << (k % 64);
    }
  // Within radius + sqrt(2) voxels of a column's centre: every column the cylinder can touch
  // from a body centre anywhere in that column (half a diagonal to the body, half to the square).
  const double reach = footprint_radius_m / frame_.resolution_m() + std::sqrt(2.0);
  const int span = static_cast<int>(std::ceil(reach));
  std::vector<std::pair<int, int>> disc;
  for (int dj = -span; dj <= span; ++dj)
    for (int di = -span; di <= span; ++di)
      if (di * di + dj * dj <= reach * reach) disc.emplace_back(di, dj);
  reach_.assign(columns * words_, 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      std::uint64_t* out = reach_.data() + (static_cast<std::size_t>(j) * nx + i) * words_;
      for (const auto& [di, dj] : disc) {
        const int ci = i + di, cj = j + dj;
        if (ci < 0 || cj < 0 || ci >= nx || cj >= ny) {
          // Outside the grid every voxel is unknown.
          if (unknown_blocks_) std::fill(out, out + words_, ~std::uint64_t{0});
          continue;
        }
        const std::uint64_t* in = own.data() + (static_cast<std::size_t>(cj) * nx + ci) * words_;
        for (int w = 0; w < words_; ++w) out[w] |= in[w];
      }
    }
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
