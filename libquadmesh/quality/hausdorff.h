// Two-sided Hausdorff distance between triangulated surfaces, estimated on
// samples: the largest distance from a sample of one surface to the other surface
// (exact point-triangle distances through a CGAL AABB tree), in both directions.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <cmath>
#include <vector>

namespace qm {

struct HausdorffOptions {
  /// Edges are sampled at multiples of 1/subdivisions (k >= 2, even: the midpoint
  /// is one of them) and each triangle at its centroid and the interior points of
  /// the barycentric lattice (i, j, l) / k, i, j, l >= 1. Default: 3 interior points.
  int subdivisions = 4;
};

struct HausdorffDistance {
  double forward = 0;   ///< max over the samples of A of the distance to B
  double backward = 0;  ///< max over the samples of B of the distance to A
  /// max(forward, backward); NaN if either is NaN
  double value() const {
    if (std::isnan(forward) || std::isnan(backward)) return std::nan("");
    return forward > backward ? forward : backward;
  }
};

/// The sample points of a triangulated surface: its referenced points, points on
/// every distinct edge (including the midpoint), and per triangle its centroid
/// and interior barycentric lattice points (HausdorffOptions).
std::vector<Vec3> surface_samples(const std::vector<Vec3>& points,
                                  const std::vector<Triangle>& triangles,
                                  const HausdorffOptions& options = {});

/// The sample farthest from a surface, and its distance.
struct FarthestSample {
  double distance = 0;  ///< NaN when there is no triangle or no sample
  Vec3 point = Vec3::Zero();
};

/// The sample of `samples` farthest from the surface (`points`, `triangles`).
/// Degenerate (zero-area) triangles are skipped.
FarthestSample farthest_sample(const std::vector<Vec3>& samples, const std::vector<Vec3>& points,
                               const std::vector<Triangle>& triangles);

/// The largest distance from one of `samples` to the surface (`points`,
/// `triangles`): farthest_sample(...).distance.
double max_distance_to_surface(const std::vector<Vec3>& samples, const std::vector<Vec3>& points,
                               const std::vector<Triangle>& triangles);

/// Two-sided Hausdorff distance between surfaces A and B, each sampled with
/// surface_samples(). The sampled value is a lower bound of the true distance
/// that is exact when the farthest point is a sample (e.g. a vertex).
HausdorffDistance two_sided_hausdorff(const std::vector<Vec3>& points_a,
                                      const std::vector<Triangle>& triangles_a,
                                      const std::vector<Vec3>& points_b,
                                      const std::vector<Triangle>& triangles_b,
                                      const HausdorffOptions& options = {});

/// The diagonal of the axis-aligned bounding box of the points used by `triangles`
/// (0 when there are none).
double bounding_box_diagonal(const std::vector<Vec3>& points,
                             const std::vector<Triangle>& triangles);

}  // namespace qm
