#include "libquadmesh/param/rounding_scale.h"

#include "libquadmesh/core/error.h"

#include <algorithm>
#include <cmath>

namespace qm {

std::vector<double> rounded_periods(const SurfaceAdjacency& adjacency, const FaceMap& h, const NamedLoops& loops) {
  std::vector<double> periods;
  std::vector<Complex> handle;
  for (const auto& loop : loops.handles) handle.push_back(path_integral(adjacency, h, loop, true));
  for (const Complex& p : handle) periods.push_back(p.real());
  for (const Complex& p : handle) periods.push_back(p.imag());
  for (std::size_t k = 1; k < loops.boundaries.size(); ++k)
    periods.push_back(path_integral(adjacency, h, loops.boundaries[k], true).real());
  for (const auto& bridge : loops.bridges) periods.push_back(path_integral(adjacency, h, bridge, false).imag());
  return periods;
}

double rounding_residual(const std::vector<double>& periods, double s) {
  double sum = 0;
  for (double p : periods) {
    const double x = s * p;
    sum += (x - round_nonzero(x)) * (x - round_nonzero(x));
  }
  return sum;
}

/// A scale replaces the best so far only if its residual is lower by more than
/// this (cells^2): rounding noise does not move the scale.
constexpr double residual_margin = 1e-12;

double rounding_scale(const std::vector<double>& periods, double s0, double window) {
  QM_ASSERT(s0 > 0 && window >= 0);
  double fastest = 0;
  for (double p : periods) fastest = std::max(fastest, std::abs(p));
  if (fastest == 0 || window == 0) return s0;
  // s p turns through one integer as s moves by 1 / |p|: 50 samples per turn of the
  // fastest period, at least 200 over the window, from s0 outwards
  const double step = std::min(window * s0 / 100, 1.0 / (50 * fastest));
  const long n = static_cast<long>(std::ceil(window * s0 / step));
  double best = s0, best_residual = rounding_residual(periods, s0);
  for (long i = 1; i <= n; ++i)
    for (const double s : {s0 - static_cast<double>(i) * step, s0 + static_cast<double>(i) * step}) {
      if (std::abs(s - s0) > window * s0 || s <= 0) continue;
      if (const double e = rounding_residual(periods, s); e < best_residual - residual_margin) {
        best_residual = e;
        best = s;
      }
    }
  return best;
}

}  // namespace qm
