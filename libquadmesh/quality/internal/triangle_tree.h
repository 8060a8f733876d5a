// Closest points on a set of 3D triangles or segments (CGAL AABB trees): the
// distance queries of the Hausdorff estimate and of the quad refinement's
// deviation and placement (on S, and on S's boundary polylines).
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <memory>
#include <utility>
#include <vector>

namespace qm {

class TriangleTree {
 public:
  TriangleTree();
  ~TriangleTree();
  TriangleTree(TriangleTree&&) noexcept;
  TriangleTree& operator=(TriangleTree&&) noexcept;

  /// The triangles of a soup, each with its index as id.
  TriangleTree(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles);

  /// Adds a triangle with the caller's id; a degenerate (zero-area) triangle is
  /// left out (the edges of its neighbours cover it). Call build() after the last.
  void add(const Vec3& a, const Vec3& b, const Vec3& c, int id);
  void build();

  bool empty() const;
  /// The closest point on the triangles and the id of its triangle (not empty()).
  std::pair<Vec3, int> closest(const Vec3& p) const;
  /// closest() of each point, in order, the points shared out over the worker
  /// threads (core/parallel.h: the same answers whatever their number).
  std::vector<std::pair<Vec3, int>> closest_to_each(const std::vector<Vec3>& points) const;
  double squared_distance(const Vec3& p) const;
  /// squared_distance(p), the same number, and the closest point it is measured to.
  std::pair<double, Vec3> squared_distance_and_closest(const Vec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The same for segments (a boundary polyline: segment k from a to b).
class SegmentTree {
 public:
  SegmentTree();
  ~SegmentTree();
  SegmentTree(SegmentTree&&) noexcept;
  SegmentTree& operator=(SegmentTree&&) noexcept;

  /// Adds a segment with the caller's id. Call build() after the last.
  void add(const Vec3& a, const Vec3& b, int id);
  void build();

  bool empty() const;
  /// The closest point on the segments and the id of its segment (not empty()).
  std::pair<Vec3, int> closest(const Vec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace qm
