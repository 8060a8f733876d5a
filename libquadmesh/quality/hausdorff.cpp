#include "libquadmesh/quality/hausdorff.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
  std::vector<std::pair<int, int>> edges;  // each distinct edge once, in order
  edges.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int c = 0; c < 3; ++c) {
      used[static_cast<std::size_t>(t[c])] = 1;
      const int a = t[c], b = t[(c + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
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

namespace {

/// farthest_sample() takes the samples in blocks of this many, the same blocks
/// whatever the number of threads, after a first look at every this many-th sample.
constexpr std::size_t sample_block = 256;
constexpr std::size_t first_look_stride = 64;
/// A sample is passed over when a point of the surface is nearer to it than the
/// farthest distance known by more than this (relative, on the squared
/// distances): well above the closest-point query's round-off.
constexpr double pass_over_margin = 1e-9;

/// The farthest of samples [begin, end) and its squared distance (-1: none was
/// queried). `known` is the squared distance of a sample already queried, a lower
/// bound of the farthest. The closest point of the sample queried last is a point
/// of the surface, so its distance to the next sample bounds that sample's
/// distance from above: where the bound is below the farthest known, the sample
/// cannot be the farthest and its query is not made (consecutive samples lie a
/// fraction of a triangle apart, so most are passed over). The farthest sample,
/// and its number, are those of querying every sample.
std::pair<double, std::size_t> farthest_in_block(const TriangleTree& tree, const std::vector<Vec3>& samples,
                                                 std::size_t begin, std::size_t end, double known) {
  double worst = -1;
  std::size_t at = begin;
  bool queried = false;
  Vec3 last_closest = Vec3::Zero();
  for (std::size_t i = begin; i < end; ++i) {
    const double bound = std::max(known, worst) * (1 - pass_over_margin);
    if (queried && (samples[i] - last_closest).squaredNorm() < bound) continue;
    const auto [squared, closest] = tree.squared_distance_and_closest(samples[i]);
    last_closest = closest;
    queried = true;
    if (squared > worst) {
      worst = squared;
      at = i;
    }
  }
  return {worst, at};
}

}  // namespace

FarthestSample farthest_sample(const std::vector<Vec3>& samples, const std::vector<Vec3>& points,
                               const std::vector<Triangle>& triangles) {
  const TriangleTree tree(points, triangles);
  FarthestSample far;
  if (tree.empty() || samples.empty()) {
    far.distance = std::numeric_limits<double>::quiet_NaN();
    return far;
  }
  const std::vector<double> looked = parallel_map<double>(
      (samples.size() + first_look_stride - 1) / first_look_stride,
      [&](std::size_t k) { return tree.squared_distance(samples[k * first_look_stride]); });
  const double known = *std::max_element(looked.begin(), looked.end());
  const std::size_t blocks = (samples.size() + sample_block - 1) / sample_block;
  const std::vector<std::pair<double, std::size_t>> farthest =
      parallel_map<std::pair<double, std::size_t>>(blocks, [&](std::size_t b) {
        return farthest_in_block(tree, samples, b * sample_block, std::min(samples.size(), (b + 1) * sample_block),
                                 known);
      });
  double worst = -1;
  for (const auto& [squared, i] : farthest)
    if (squared > worst) {
      worst = squared;
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
