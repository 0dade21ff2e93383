#include "ceilplan/environment/disc_area.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ceilplan::environment {
namespace {

// Antiderivative of sqrt(R^2 - u^2).
double halfChordIntegral(double u, double radius) {
  const double clamped = std::clamp(u, -radius, radius);
  return 0.5 * (clamped * std::sqrt(std::max(0.0, radius * radius - clamped * clamped)) +
                radius * radius * std::asin(clamped / radius));
}

}  // namespace

double discRectangleOverlap_m2(const Eigen::Vector2d& centre_m, double radius_m, const Eigen::Vector2d& min_m,
                               const Eigen::Vector2d& max_m) {
  // Work relative to the disc's centre: the overlap is the integral over u of the length of
  // [y0, y1] within [-h(u), h(u)], h(u) = sqrt(R^2 - u^2). Between breakpoints each bound is
  // either a rectangle side or the circle, so every piece integrates in closed form.
  const double r = radius_m;
  const double u0 = std::max(min_m.x() - centre_m.x(), -r);
  const double u1 = std::min(max_m.x() - centre_m.x(), r);
  const double y0 = min_m.y() - centre_m.y();
  const double y1 = max_m.y() - centre_m.y();
  if (u0 >= u1 || y0 >= y1 || y0 >= r || y1 <= -r) return 0.0;

  std::array<double, 6> breaks{};
  int count = 0;
  breaks[count++] = u0;
  for (const double y : {y0, y1}) {
    if (std::abs(y) >= r) continue;
    const double u = std::sqrt(r * r - y * y);  // where the circle crosses the line v = y
    for (const double candidate : {-u, u})
      if (candidate > u0 && candidate < u1) breaks[count++] = candidate;
  }
  breaks[count++] = u1;
  for (int p = 1; p < count; ++p)  // at most six values: insertion sort
    for (int q = p; q > 0 && breaks[q - 1] > breaks[q]; --q) std::swap(breaks[q - 1], breaks[q]);

  double area = 0.0;
  for (int p = 0; p + 1 < count; ++p) {
    const double a = breaks[p];
    const double b = breaks[p + 1];
    if (b <= a) continue;
    const double middle = 0.5 * (a + b);
    const double h = std::sqrt(std::max(0.0, r * r - middle * middle));
    if (std::min(y1, h) <= std::max(y0, -h)) continue;  // the strip misses the disc here
    const double circle = halfChordIntegral(b, r) - halfChordIntegral(a, r);
    const double upper = y1 < h ? y1 * (b - a) : circle;
    const double lower = y0 > -h ? y0 * (b - a) : -circle;
    area += upper - lower;
  }
  return area;
}

}  // namespace ceilplan::environment
