#include "libquadmesh/quality/internal/triangle_tree.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

namespace qm {

namespace {
// closest points are constructions, which no kernel makes exact: the double kernel
// without predicate filters gives the same points, and the quad stages on a CAD
// plate a fifth faster (issue 21)
using K = CGAL::Simple_cartesian<double>;
using Triangle3 = K::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

using Segment3 = K::Segment_3;
using SegmentPrimitive = CGAL::AABB_segment_primitive<K, std::vector<Segment3>::const_iterator>;
using SegmentAabb = CGAL::AABB_tree<CGAL::AABB_traits<K, SegmentPrimitive>>;

K::Point_3 cgal(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
Vec3 eigen(const K::Point_3& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

struct TriangleTree::Impl {
  std::vector<Triangle3> triangles;
  std::vector<int> ids;
  std::unique_ptr<Tree> tree;
};

TriangleTree::TriangleTree() : impl_(std::make_unique<Impl>()) {}
TriangleTree::~TriangleTree() = default;
TriangleTree::TriangleTree(TriangleTree&&) noexcept = default;
TriangleTree& TriangleTree::operator=(TriangleTree&&) noexcept = default;

TriangleTree::TriangleTree(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
    : TriangleTree() {
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Triangle& t = triangles[f];
    add(points[static_cast<std::size_t>(t[0])], points[static_cast<std::size_t>(t[1])],
        points[static_cast<std::size_t>(t[2])], static_cast<int>(f));
  }
  build();
}

void TriangleTree::add(const Vec3& a, const Vec3& b, const Vec3& c, int id) {
  Triangle3 t(cgal(a), cgal(b), cgal(c));
  if (t.is_degenerate()) return;
  impl_->triangles.push_back(t);
  impl_->ids.push_back(id);
}

void TriangleTree::build() {
  impl_->tree = std::make_unique<Tree>(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree->accelerate_distance_queries();
}

bool TriangleTree::empty() const { return impl_->triangles.empty(); }

std::pair<Vec3, int> TriangleTree::closest(const Vec3& p) const {
  QM_ASSERT(impl_->tree && !empty());
  const auto hit = impl_->tree->closest_point_and_primitive(cgal(p));
  return {eigen(hit.first),
          impl_->ids[static_cast<std::size_t>(hit.second - impl_->triangles.cbegin())]};
}

std::vector<std::pair<Vec3, int>> TriangleTree::closest_to_each(const std::vector<Vec3>& points) const {
  return parallel_map<std::pair<Vec3, int>>(points.size(), [&](std::size_t i) { return closest(points[i]); });
}

double TriangleTree::squared_distance(const Vec3& p) const { return squared_distance_and_closest(p).first; }

std::pair<double, Vec3> TriangleTree::squared_distance_and_closest(const Vec3& p) const {
  QM_ASSERT(impl_->tree && !empty());
  // what AABB_tree::squared_distance computes, keeping the point: one computation
  // for both, so that the farthest sample's bounds and the distances agree
  const K::Point_3 q = cgal(p);
  const K::Point_3 closest = impl_->tree->closest_point(q);
  return {K::Compute_squared_distance_3()(q, closest), eigen(closest)};
}

struct SegmentTree::Impl {
  std::vector<Segment3> segments;
  std::vector<int> ids;
  std::unique_ptr<SegmentAabb> tree;
};

SegmentTree::SegmentTree() : impl_(std::make_unique<Impl>()) {}
SegmentTree::~SegmentTree() = default;
SegmentTree::SegmentTree(SegmentTree&&) noexcept = default;
SegmentTree& SegmentTree::operator=(SegmentTree&&) noexcept = default;

void SegmentTree::add(const Vec3& a, const Vec3& b, int id) {
  impl_->segments.emplace_back(cgal(a), cgal(b));
  impl_->ids.push_back(id);
}

void SegmentTree::build() {
  impl_->tree = std::make_unique<SegmentAabb>(impl_->segments.cbegin(), impl_->segments.cend());
  impl_->tree->accelerate_distance_queries();
}

bool SegmentTree::empty() const { return impl_->segments.empty(); }

std::pair<Vec3, int> SegmentTree::closest(const Vec3& p) const {
  QM_ASSERT(impl_->tree && !empty());
  const auto hit = impl_->tree->closest_point_and_primitive(cgal(p));
  return {eigen(hit.first), impl_->ids[static_cast<std::size_t>(hit.second - impl_->segments.cbegin())]};
}

}  // namespace qm
