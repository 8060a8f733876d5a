#include "libquadmesh/forms/coarsen.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace qm {

namespace {

/// A pass that collapses fewer than this fraction of the vertices ends the coarsening.
constexpr double last_pass_fraction = 0.002;
constexpr int max_passes = 40;

double shape_quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  if (squares == 0) return 0;
  return 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / squares;
}

/// The mutable triangulation the collapses work on: triangles die, vertices die,
/// points never move.
class Collapser {
 public:
  Collapser(const TriangleSoup& soup, const CoarsenOptions& options)
      : soup_(soup), options_(options), triangles_(soup.triangles), alive_(soup.triangles.size(), 1),
        faces_(soup.points.size()), boundary_(soup.points.size(), 0) {
    for (std::size_t f = 0; f < triangles_.size(); ++f)
      for (int v : triangles_[f]) faces_[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
    const SurfaceAdjacency adjacency = surface_adjacency(soup);
    boundary_ = adjacency.boundary_vertex;
    cos_normal_ = std::cos(options.max_normal_turn_deg * M_PI / 180.0);
    cos_boundary_ = std::cos(options.max_boundary_turn_deg * M_PI / 180.0);
    max_edge_ = options.max_edge_factor * options.edge_length;
  }

  /// One pass over the edges shorter than L, shortest first; returns the collapses.
  std::size_t pass() {
    std::vector<std::tuple<double, int, int>> edges;
    for (std::size_t f = 0; f < triangles_.size(); ++f) {
      if (!alive_[f]) continue;
      const Triangle& t = triangles_[f];
      for (int i = 0; i < 3; ++i) {
        const int a = t[i], b = t[(i + 1) % 3];
        // each interior edge once (from the side with a < b); a boundary edge from its one side
        if (a > b && !is_boundary_edge(a, b)) continue;
        const double length = (point(a) - point(b)).norm();
        if (length < options_.edge_length) edges.emplace_back(length, std::min(a, b), std::max(a, b));
      }
    }
    std::sort(edges.begin(), edges.end());
    std::size_t collapses = 0;
    for (const auto& [length, a, b] : edges) {
      if (faces_[static_cast<std::size_t>(a)].empty() || faces_[static_cast<std::size_t>(b)].empty()) continue;
      if (try_collapse(b, a) || try_collapse(a, b)) ++collapses;
    }
    return collapses;
  }

  TriangleSoup result() const {
    TriangleSoup out;
    std::vector<int> index(soup_.points.size(), -1);
    for (std::size_t v = 0; v < soup_.points.size(); ++v) {
      if (faces_[v].empty()) continue;
      index[v] = static_cast<int>(out.points.size());
      out.points.push_back(soup_.points[v]);
      if (!soup_.point_labels.empty()) out.point_labels.push_back(soup_.point_labels[v]);
      else out.point_labels.push_back(static_cast<std::int64_t>(v));
    }
    for (std::size_t f = 0; f < triangles_.size(); ++f) {
      if (!alive_[f]) continue;
      const Triangle& t = triangles_[f];
      out.triangles.push_back({index[static_cast<std::size_t>(t[0])], index[static_cast<std::size_t>(t[1])],
                               index[static_cast<std::size_t>(t[2])]});
      out.triangle_labels.push_back(soup_.triangle_label(static_cast<int>(f)));
    }
    return out;
  }

 private:
  const Vec3& point(int v) const { return soup_.points[static_cast<std::size_t>(v)]; }

  /// Live triangles holding both a and b.
  int shared_faces(int a, int b, int opposite[2]) const {
    int count = 0;
    for (int f : faces_[static_cast<std::size_t>(a)]) {
      const Triangle& t = triangles_[static_cast<std::size_t>(f)];
      if (t[0] != b && t[1] != b && t[2] != b) continue;
      if (count < 2) opposite[count] = t[0] != a && t[0] != b ? t[0] : t[1] != a && t[1] != b ? t[1] : t[2];
      ++count;
    }
    return count;
  }
  bool is_boundary_edge(int a, int b) const {
    int opposite[2];
    return shared_faces(a, b, opposite) == 1;
  }

  /// The neighbours of v on its boundary loop: (previous, next), following the triangles' orientation.
  std::pair<int, int> boundary_neighbours(int v) const {
    int previous = -1, next = -1;
    for (int f : faces_[static_cast<std::size_t>(v)]) {
      const Triangle& t = triangles_[static_cast<std::size_t>(f)];
      for (int i = 0; i < 3; ++i) {
        if (t[i] != v) continue;
        const int n = t[(i + 1) % 3], p = t[(i + 2) % 3];
        if (is_boundary_edge(v, n)) next = n;
        if (is_boundary_edge(v, p)) previous = p;
      }
    }
    return {previous, next};
  }

  /// Removing boundary point r, merged into its boundary neighbour k: the boundary
  /// must be nearly straight at r and pass near it afterwards.
  bool boundary_removable(int r, int k) const {
    const auto [previous, next] = boundary_neighbours(r);
    if (previous < 0 || next < 0 || previous == next) return false;
    const int other = previous == k ? next : previous;
    if (other == k) return false;
    const Vec3 in = (point(r) - point(previous)).normalized(), out = (point(next) - point(r)).normalized();
    if (in.dot(out) < cos_boundary_) return false;
    const Vec3 d = point(other) - point(k);
    const double t = std::clamp((point(r) - point(k)).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
    return (point(k) + t * d - point(r)).norm() <= options_.boundary_tolerance * options_.edge_length;
  }

  /// The link condition: the common neighbours of r and k are the triangles'
  /// opposite corners on the edge alone.
  bool link_condition(int r, int k, int shared, const int opposite[2]) {
    ++stamp_;
    if (mark_.size() < soup_.points.size()) mark_.assign(soup_.points.size(), 0);
    for (int f : faces_[static_cast<std::size_t>(k)])
      for (int v : triangles_[static_cast<std::size_t>(f)]) mark_[static_cast<std::size_t>(v)] = stamp_;
    for (int f : faces_[static_cast<std::size_t>(r)])
      for (int v : triangles_[static_cast<std::size_t>(f)]) {
        if (v == r || v == k || mark_[static_cast<std::size_t>(v)] != stamp_) continue;
        if (v != opposite[0] && (shared < 2 || v != opposite[1])) return false;
      }
    return true;
  }

  /// Collapse r into k (r's point disappears) when every check passes.
  bool try_collapse(int r, int k) {
    int opposite[2] = {-1, -1};
    const int shared = shared_faces(r, k, opposite);
    if (shared == 0) return false;  // no longer an edge
    const bool boundary_edge = shared == 1;
    const bool r_boundary = boundary_[static_cast<std::size_t>(r)] != 0;
    if (r_boundary && !boundary_edge) return false;  // pinch, or the boundary moving inside
    if (r_boundary && !boundary_removable(r, k)) return false;
    if (!link_condition(r, k, shared, opposite)) return false;
    double worst_before = 1, worst_after = 1;
    for (int f : faces_[static_cast<std::size_t>(r)]) {
      const Triangle& t = triangles_[static_cast<std::size_t>(f)];
      if (t[0] == k || t[1] == k || t[2] == k) continue;
      Triangle moved = t;
      for (int& v : moved)
        if (v == r) v = k;
      const Vec3 n0 = (point(t[1]) - point(t[0])).cross(point(t[2]) - point(t[0]));
      const Vec3 n1 = (point(moved[1]) - point(moved[0])).cross(point(moved[2]) - point(moved[0]));
      const double l0 = n0.norm(), l1 = n1.norm();
      if (l1 == 0 || n0.dot(n1) < cos_normal_ * l0 * l1) return false;
      for (int i = 0; i < 3; ++i)
        if ((point(moved[i]) - point(moved[(i + 1) % 3])).norm() > max_edge_) return false;
      worst_before = std::min(worst_before, shape_quality(point(t[0]), point(t[1]), point(t[2])));
      worst_after = std::min(worst_after, shape_quality(point(moved[0]), point(moved[1]), point(moved[2])));
    }
    if (worst_after < options_.min_quality && worst_after < worst_before) return false;
    // the collapse: the triangles on the edge die, the others take k for r
    std::vector<int>& to = faces_[static_cast<std::size_t>(k)];
    for (int f : faces_[static_cast<std::size_t>(r)]) {
      Triangle& t = triangles_[static_cast<std::size_t>(f)];
      if (t[0] == k || t[1] == k || t[2] == k) {
        alive_[static_cast<std::size_t>(f)] = 0;
        for (int v : t) {
          if (v == r) continue;
          auto& list = faces_[static_cast<std::size_t>(v)];
          list.erase(std::find(list.begin(), list.end(), f));
        }
        continue;
      }
      for (int& v : t)
        if (v == r) v = k;
      to.push_back(f);
    }
    faces_[static_cast<std::size_t>(r)].clear();
    faces_[static_cast<std::size_t>(r)].shrink_to_fit();
    return true;
  }

  const TriangleSoup& soup_;
  const CoarsenOptions& options_;
  std::vector<Triangle> triangles_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> faces_;  ///< live triangles at each point; empty: the point is gone
  std::vector<char> boundary_;
  std::vector<unsigned> mark_;
  unsigned stamp_ = 0;
  double cos_normal_ = 0, cos_boundary_ = 0, max_edge_ = 0;
};

/// chi and the number of boundary loops of an oriented manifold soup.
std::pair<int, std::size_t> topology(const TriangleSoup& soup) {
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  return {euler_characteristic(adjacency), adjacency.boundary_loops.size()};
}

}  // namespace

TriangleSoup coarsen(const TriangleSoup& soup, const CoarsenOptions& options, CoarsenReport* report) {
  QM_ASSERT(options.edge_length > 0);
  Collapser collapser(soup, options);
  CoarsenReport r;
  while (r.passes < max_passes) {
    const std::size_t collapses = collapser.pass();
    ++r.passes;
    r.collapses += collapses;
    if (static_cast<double>(collapses) < last_pass_fraction * static_cast<double>(soup.points.size())) break;
  }
  TriangleSoup out = collapser.result();
  out.cad = soup.cad;
  out.cad.edges.clear();  // their point indices no longer apply
  r.topology_kept = topology(out) == topology(soup);
  if (report) *report = r;
  return r.topology_kept ? out : soup;
}

}  // namespace qm
