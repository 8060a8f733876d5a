#include "libquadmesh/quality/hausdorff.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace qm {

std::vector<Vec3> surface_samples(const std::vector<Vec3>& points,
                                  const std::vector<Triangle>& triangles,
                                  const HausdorffOptions& options) {
  QM_ASSERT_MSG(options.subdivisions >= 2 && options.subdivisions % 2 == 0,
                "subdivisions must be even and at least 2");
  const int k = options.subdivisions;
  std::vector<Vec3> samples;
  std::vector<char> used(points.size(), 0);
  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : triangles)
    for (int c = 0; c < 3; ++c) {
      used[static_cast<std::size_t>(t[c])] = 1;
      const int a = t[c], b = t[(c + 1) % 3];
      edges.emplace(std::min(a, b), std::max(a, b));
    }
  for (std::size_t i = 0; i < points.size(); ++i)
    if (used[i]) samples.push_back(points[i]);
  for (const auto& [a, b] : edges)
    for (int j = 1; j < k; ++j) {
      const double s = static_cast<double>(j) / k;
      samples.push_back((1 - s) * points[static_cast<std::size_t>(a)] +
                        s * points[static_cast<std::size_t>(b)]);
    }
  for (const Triangle& t : triangles) {
    const Vec3& p = points[static_cast<std::size_t>(t[0])];
    const Vec3& q = points[static_cast<std::size_t>(t[1])];
    const Vec3& r = points[static_cast<std::size_t>(t[2])];
    samples.push_back((p + q + r) / 3.0);
    for (int i = 1; i < k; ++i)
      for (int j = 1; i + j < k; ++j) {
        const double wi = static_cast<double>(i) / k, wj = static_cast<double>(j) / k;
        samples.push_back(wi * p + wj * q + (1 - wi - wj) * r);
      }
  }
  return samples;
}

FarthestSample farthest_sample(const std::vector<Vec3>& samples, const std::vector<Vec3>& points,
                               const std::vector<Triangle>& triangles) {
  const TriangleTree tree(points, triangles);
  FarthestSample far;
  if (tree.empty() || samples.empty()) {
    far.distance = std::numeric_limits<double>::quiet_NaN();
    return far;
  }
  const std::vector<double> squared =
      parallel_map<double>(samples.size(), [&](std::size_t i) { return tree.squared_distance(samples[i]); });
  double worst = -1;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (squared[i] > worst) {
      worst = squared[i];
      far.point = samples[i];
    }
  far.distance = std::sqrt(worst);
  return far;
}

double max_distance_to_surface(const std::vector<Vec3>& samples, const std::vector<Vec3>& points,
                               const std::vector<Triangle>& triangles) {
  return farthest_sample(samples, points, triangles).distance;
}

HausdorffDistance two_sided_hausdorff(const std::vector<Vec3>& points_a,
                                      const std::vector<Triangle>& triangles_a,
                                      const std::vector<Vec3>& points_b,
                                      const std::vector<Triangle>& triangles_b,
                                      const HausdorffOptions& options) {
  HausdorffDistance h;
  h.forward = max_distance_to_surface(surface_samples(points_a, triangles_a, options), points_b,
                                      triangles_b);
  h.backward = max_distance_to_surface(surface_samples(points_b, triangles_b, options), points_a,
                                       triangles_a);
  return h;
}

double bounding_box_diagonal(const std::vector<Vec3>& points,
                             const std::vector<Triangle>& triangles) {
  if (triangles.empty()) return 0;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Triangle& t : triangles)
    for (int c : t) {
      lo = lo.cwiseMin(points[static_cast<std::size_t>(c)]);
      hi = hi.cwiseMax(points[static_cast<std::size_t>(c)]);
    }
  return (hi - lo).norm();
}

}  // namespace qm
