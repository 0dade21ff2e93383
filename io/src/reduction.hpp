#pragma once
// The "reduction %" of every comparison (tables, JSON, reports): how much less the ceiling-mode
// value `with` is than the free-mode `without`, in percent of `without` (0 when that is 0).

namespace ceilplan::io {

inline double reductionPct(double with, double without) {
  return without != 0.0 ? 100.0 * (1.0 - with / without) : 0.0;
}

}  // namespace ceilplan::io
