#include "libquadmesh/cones/cone_placement.h"

#include <fmt/format.h>

#include "libquadmesh/cones/boundary_corners.h"
#include "libquadmesh/cones/cone_map.h"
#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/cross_field.h"
#include "libquadmesh/cones/fillet_corners.h"
#include "libquadmesh/cones/internal/edge_distance.h"
#include "libquadmesh/cones/protrusion_caps.h"
#include "libquadmesh/cones/smooth_cross_field.h"
#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

namespace qm {

namespace {

/// Sweeps over the cones when moving them to align the loops.
constexpr int max_alignment_passes = 8;
/// Sum of the loops' turns (radians) below which the cones stay where they are.
constexpr double alignment_goal = 1e-3;
/// Alignment moves reach at most this many times `alignment_rings` edges.
constexpr int max_widening = 3;

/// Per vertex, a third of the area of its triangles.
std::vector<double> vertex_areas(const TriangleSoup& soup) {
  std::vector<double> area(soup.points.size(), 0.0);
  for (const Triangle& t : soup.triangles) {
    const Vec3& p = soup.points[static_cast<std::size_t>(t[0])];
    const double a = 0.5 * (soup.points[static_cast<std::size_t>(t[1])] - p)
                               .cross(soup.points[static_cast<std::size_t>(t[2])] - p)
                               .norm();
    for (int v : t) area[static_cast<std::size_t>(v)] += a / 3;
  }
  return area;
}

/// Per vertex, the length of the shortest edge path to the boundary.
std::vector<double> distance_to_boundary(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) {
  std::vector<char> boundary(adjacency.boundary_vertex.begin(), adjacency.boundary_vertex.end());
  return distance_from(soup, adjacency, boundary);
}

/// Breadth-first walks of the edge rings round a vertex, with marks kept across
/// walks: a walk costs the vertices it reaches, not the surface's (the alignment
/// walks thousands of times on one placement).
class RingWalk {
 public:
  RingWalk(const TriangleSoup& soup, const SurfaceAdjacency& adjacency)
      : soup_(soup), adjacency_(adjacency), stamp_(soup.points.size(), 0), depth_(soup.points.size(), 0) {}

  /// Walks the vertices within `rings` edges of v (itself first), and stops at the
  /// first w for which stop(w) holds: true then. reached() has the vertices walked.
  template <class Stop>
  bool walk(int v, int rings, const Stop& stop) {
    ++walk_;
    reached_.assign(1, v);
    mark(v, 0);
    for (std::size_t next = 0; next < reached_.size(); ++next) {
      const int w = reached_[next];
      if (stop(w)) return true;
      const int d = depth_[static_cast<std::size_t>(w)];
      if (d == rings) continue;
      for (int f : adjacency_.vertex_faces[static_cast<std::size_t>(w)])
        for (int x : soup_.triangles[static_cast<std::size_t>(f)])
          if (stamp_[static_cast<std::size_t>(x)] != walk_) {
            mark(x, d + 1);
            reached_.push_back(x);
          }
    }
    return false;
  }

  const std::vector<int>& reached() const { return reached_; }

 private:
  void mark(int v, int depth) {
    stamp_[static_cast<std::size_t>(v)] = walk_;
    depth_[static_cast<std::size_t>(v)] = depth;
  }

  const TriangleSoup& soup_;
  const SurfaceAdjacency& adjacency_;
  std::vector<unsigned> stamp_;  ///< the walk that last reached each vertex
  std::vector<int> depth_;       ///< its depth in that walk
  std::vector<int> reached_;
  unsigned walk_ = 0;
};

/// Vertices within `rings` edges of a vertex: itself first, then breadth first.
class RingNeighbourhood {
 public:
  RingNeighbourhood(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) : rings_(soup, adjacency) {}

  const std::vector<int>& around(int v, int rings) {
    rings_.walk(v, rings, [](int) { return false; });
    return rings_.reached();
  }

 private:
  RingWalk rings_;
};

/// Whether a vertex lies within `separation` edges of an interior cone other than
/// cones[moving], or nearer than `min_distance` to one (straight line: on a fine
/// scan `separation` edges can be less than a quad or two): a breadth-first walk of
/// at most `separation` rings from the vertex (asked only of the moves worth making,
/// not of every vertex).
class ConeCrowding {
 public:
  ConeCrowding(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, int separation, double min_distance)
      : soup_(soup), adjacency_(adjacency), separation_(separation), min_distance_(min_distance),
        rings_(soup, adjacency), other_(soup.points.size(), 0) {}

  bool near_other(const std::vector<Cone>& cones, std::size_t moving, int v) {
    ++call_;  // this call's marks: the other cones' vertices
    bool any = false;
    const Vec3& at = soup_.points[static_cast<std::size_t>(v)];
    for (std::size_t j = 0; j < cones.size(); ++j) {
      const auto o = static_cast<std::size_t>(cones[j].vertex);
      if (j == moving || adjacency_.boundary_vertex[o]) continue;
      if ((soup_.points[o] - at).squaredNorm() < min_distance_ * min_distance_) return true;
      other_[o] = call_;
      any = true;
    }
    return any && rings_.walk(v, separation_, [&](int w) { return other_[static_cast<std::size_t>(w)] == call_; });
  }

 private:
  const TriangleSoup& soup_;
  const SurfaceAdjacency& adjacency_;
  int separation_;
  double min_distance_;
  RingWalk rings_;
  std::vector<unsigned> other_;  ///< the call that last marked each vertex another cone's
  unsigned call_ = 0;
};

/// Moves interior cones, one at a time, to where the field meets every boundary
/// loop (and goes round every handle) closest to a whole quarter turn
/// (cross_field.h LoopTurns: every row), within
/// `rings` edges of where they are; the cones at `pinned` vertices stay. Returns
/// the largest turn left (radians).
double align_loops_by_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const LoopTurns& model,
                            const std::vector<double>& curvature, const std::vector<char>& eligible,
                            const std::vector<char>& pinned, int rings, int separation, double min_distance,
                            std::vector<Cone>& cones) {
  const std::size_t loops = model.rows();
  std::vector<double> kappa = target_curvature(adjacency, quads_per_vertex(adjacency, cones));
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(kappa.size()));
  for (std::size_t v = 0; v < kappa.size(); ++v) rhs[static_cast<Eigen::Index>(v)] = kappa[v] - curvature[v];
  std::vector<double> dot(loops, 0.0);
  for (std::size_t l = 0; l < loops; ++l)
    if (static_cast<int>(l) != model.reference) dot[l] = model.gradient[l].dot(rhs);
  auto cost = [&](const std::vector<double>& d) {
    double c = 0;
    for (std::size_t l = 0; l < loops; ++l)
      if (static_cast<int>(l) != model.reference) c += std::abs(quarter_turn_remainder(model.offset[l] - d[l]));
    return c;
  };
  double current = cost(dot);
  ConeCrowding crowding(soup, adjacency, separation, min_distance);
  RingNeighbourhood ring(soup, adjacency);
  // when no move within `rings` edges helps any more and the loops are still
  // turned, the cones may go farther (on a coarse triangulation `rings` edges
  // are a few quads only)
  for (int widen = 1; widen <= max_widening && current > alignment_goal; ++widen) {
    for (int pass = 0; pass < max_alignment_passes && current > alignment_goal; ++pass) {
      bool moved = false;
      for (Cone& cone : cones) {
        const auto at = static_cast<std::size_t>(cone.vertex);
        if (adjacency.boundary_vertex[at] || pinned[at]) continue;
        const double k = (4 - cone.quads) * quarter_turn;
        int best = -1;
        std::vector<double> best_dot;
        const auto moving = static_cast<std::size_t>(&cone - cones.data());
        for (int w : ring.around(cone.vertex, widen * rings)) {
          const auto sw = static_cast<std::size_t>(w);
          if (!eligible[sw]) continue;
          std::vector<double> trial = dot;
          for (std::size_t l = 0; l < loops; ++l)
            if (static_cast<int>(l) != model.reference)
              trial[l] += k * (model.gradient[l][w] - model.gradient[l][cone.vertex]);
          const double c = cost(trial);
          if (c < current - 1e-9 && !crowding.near_other(cones, moving, w)) {
            current = c;
            best = w;
            best_dot = trial;
          }
        }
        if (best < 0) continue;
        cone.vertex = best;
        dot = best_dot;
        moved = true;
      }
      if (!moved) break;
    }
  }
  double worst = 0;
  for (std::size_t l = 0; l < loops; ++l)
    if (static_cast<int>(l) != model.reference)
      worst = std::max(worst, std::abs(quarter_turn_remainder(model.offset[l] - dot[l])));
  return worst;
}

/// The area-weighted variance of u about its mean: the spread of the quad sizes
/// (log scale) that the band [0.5, 2] x the size bounds.
double size_spread(const Eigen::VectorXd& u, const std::vector<double>& area, double& mean) {
  double total = 0, sum = 0;
  for (Eigen::Index v = 0; v < u.size(); ++v) {
    total += area[static_cast<std::size_t>(v)];
    sum += area[static_cast<std::size_t>(v)] * u[v];
  }
  mean = sum / total;
  double variance = 0;
  for (Eigen::Index v = 0; v < u.size(); ++v)
    variance += area[static_cast<std::size_t>(v)] * (u[v] - mean) * (u[v] - mean);
  return variance / total;
}

/// Moves interior cones, one ring step at a time, so that the quad sizes spread
/// less: the area-weighted variance V of u. Moving a cone of curvature k from a
/// to b changes the metric's right side by k (e_b - e_a), so to first order
/// dV = 2 k (g_b - g_a) with g = L^-1 (A (u - mean u)) (L symmetric): one solve
/// ranks every move. A move is kept when the re-solved V drops and the loops'
/// turns (LoopTurns) stay within `slack` of whole quarter turns or no worse than
/// they were. The cones at `pinned` vertices stay. The sizes are the metric's with
/// the acute corners' singular part left out for quads of `tip_size` (tip_scale.h;
/// 0: not).
void relax_cones_for_size(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const ConeMetricSolver& solver,
                          const LoopTurns& model, const std::vector<double>& curvature,
                          const std::vector<double>& area, const std::vector<char>& eligible,
                          const std::vector<char>& pinned, int separation, double min_distance, int passes,
                          double slack, double tip_size, std::vector<Cone>& cones) {
  auto alignment_cost = [&](const std::vector<Cone>& trial) {
    if (adjacency.boundary_loops.size() < 2) return 0.0;
    const std::vector<double> kappa = target_curvature(adjacency, quads_per_vertex(adjacency, trial));
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(kappa.size()));
    for (std::size_t v = 0; v < kappa.size(); ++v) rhs[static_cast<Eigen::Index>(v)] = kappa[v] - curvature[v];
    // the boundary loops' rows only: held to the handles' rows as well, the
    // sizes relax far less (kitten's first placement: 18 interior cones against
    // 10), and the alignment after the relaxation steers the handles again
    double c = 0;
    for (std::size_t l = 0; l < adjacency.boundary_loops.size(); ++l)
      c += std::abs(model.turn(static_cast<int>(l), rhs));
    return c;
  };
  auto metric = [&](const std::vector<Cone>& trial) {
    return solver.solve(target_curvature(adjacency, quads_per_vertex(adjacency, trial)), curvature, tip_size);
  };
  Eigen::VectorXd u = metric(cones);
  double mean = 0;
  double spread = size_spread(u, area, mean);
  double aligned = alignment_cost(cones);
  ConeCrowding crowding(soup, adjacency, separation, min_distance);
  RingNeighbourhood ring(soup, adjacency);
  for (int pass = 0; pass < passes; ++pass) {
    Eigen::VectorXd weighted(u.size());
    for (Eigen::Index v = 0; v < u.size(); ++v) weighted[v] = area[static_cast<std::size_t>(v)] * (u[v] - mean);
    const Eigen::VectorXd g = solver.apply_inverse(weighted);
    bool moved = false;
    for (std::size_t i = 0; i < cones.size(); ++i) {
      const int a = cones[i].vertex;
      if (adjacency.boundary_vertex[static_cast<std::size_t>(a)] || pinned[static_cast<std::size_t>(a)]) continue;
      const double k = (4 - cones[i].quads) * quarter_turn;
      // the neighbours by the first-order drop, largest first (the first of equal
      // ones), the first not crowded by another cone taken
      std::vector<std::pair<double, int>> moves;
      for (int b : ring.around(a, 1)) {
        const double drop = k * (g[a] - g[b]);
        if (b != a && eligible[static_cast<std::size_t>(b)] && drop > 0) moves.push_back({drop, b});
      }
      std::stable_sort(moves.begin(), moves.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
      int best = -1;
      for (const auto& [drop, b] : moves)
        if (!crowding.near_other(cones, i, b)) {
          best = b;
          break;
        }
      if (best < 0) continue;
      std::vector<Cone> trial = cones;
      trial[i].vertex = best;
      const double trial_aligned = alignment_cost(trial);
      if (trial_aligned > std::max(aligned, slack)) continue;
      const Eigen::VectorXd trial_u = metric(trial);
      double trial_mean = 0;
      const double trial_spread = size_spread(trial_u, area, trial_mean);
      if (trial_spread >= spread) continue;
      cones = std::move(trial);
      u = trial_u;
      mean = trial_mean;
      spread = trial_spread;
      aligned = trial_aligned;
      moved = true;
    }
    if (!moved) break;
  }
}

/// How far the metric's quad size h e^(-(u - mean u)) strays, over the vertices
/// that are not cones (a cone's own u is the discretization's): the area share
/// within [0.5, 2] h and the largest ratio to h.
struct MetricBand {
  double share = 0;
  double largest = 0;
  double mean = 0;  ///< the area-weighted mean of u (the size h)
};

MetricBand metric_band(const Eigen::VectorXd& u, const std::vector<double>& area, const std::vector<char>& cone) {
  double total = 0, sum = 0;
  for (Eigen::Index v = 0; v < u.size(); ++v)
    if (!cone[static_cast<std::size_t>(v)]) {
      total += area[static_cast<std::size_t>(v)];
      sum += area[static_cast<std::size_t>(v)] * u[v];
    }
  const double mean = sum / total;
  MetricBand band;
  band.mean = mean;
  for (Eigen::Index v = 0; v < u.size(); ++v) {
    if (cone[static_cast<std::size_t>(v)]) continue;
    if (std::abs(u[v] - mean) <= std::log(2.0)) band.share += area[static_cast<std::size_t>(v)] / total;
    band.largest = std::max(band.largest, std::exp(mean - u[v]));
  }
  return band;
}

/// The largest quad size the metric makes, seen a quad at a time: per vertex that
/// is no cone, the area-weighted mean of u over the vertices no cone nearer than
/// `radius` (straight line, reached along the edges), h e^(-(that - mean u))
/// over h at its largest. A scan's boundary tooth that the corners make straight
/// (a vertex turning by 70-100 degrees, a fraction of a quad long) drops u at its
/// own vertex only: the pointwise largest there is 10-13 x (bunny-open), the
/// quads the lattice puts there are not.
double quad_scale_largest(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                          const std::vector<double>& area, const std::vector<char>& cone, double mean,
                          double radius) {
  std::vector<unsigned> stamp(soup.points.size(), 0);
  unsigned walk = 0;
  double largest = 0;
  std::vector<int> queue;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (cone[v]) continue;
    ++walk;
    queue.assign(1, static_cast<int>(v));
    stamp[v] = walk;
    double weight = 0, sum = 0;
    for (std::size_t next = 0; next < queue.size(); ++next) {
      const auto w = static_cast<std::size_t>(queue[next]);
      weight += area[w];
      sum += area[w] * u[static_cast<Eigen::Index>(w)];
      for (int f : adjacency.vertex_faces[w])
        for (int x : soup.triangles[static_cast<std::size_t>(f)]) {
          const auto xi = static_cast<std::size_t>(x);
          if (stamp[xi] == walk) continue;
          stamp[xi] = walk;
          if (!cone[xi] && (soup.points[xi] - soup.points[v]).squaredNorm() < radius * radius) queue.push_back(x);
        }
    }
    if (weight > 0) largest = std::max(largest, std::exp(mean - sum / weight));
  }
  return largest;
}

/// Sets marks[v] = value for every point v nearer than `radius` to `at`.
void mark_within(const std::vector<Vec3>& points, const Vec3& at, double radius, char value, std::vector<char>& marks) {
  for (std::size_t v = 0; v < points.size(); ++v)
    if ((points[v] - at).squaredNorm() < radius * radius) marks[v] = value;
}

/// The boundary vertex with the highest u that may take a boundary cone (a
/// straight boundary point in three quads): no vertex of `eligible` within
/// `room` of it along the edges (an interior cone there has no place to go),
/// and `spacing` (straight-line) from every cone. -1 when there is none.
int cramped_boundary_extreme(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                             const std::vector<char>& eligible, double room, double spacing,
                             const std::vector<Cone>& cones) {
  const std::vector<double> to_eligible = distance_from(soup, adjacency, eligible);
  int best = -1;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (!adjacency.boundary_vertex[v] || to_eligible[v] <= room) continue;
    if (best >= 0 && u[static_cast<Eigen::Index>(v)] <= u[best]) continue;
    const bool apart = std::none_of(cones.begin(), cones.end(), [&](const Cone& c) {
      return (soup.points[v] - soup.points[static_cast<std::size_t>(c.vertex)]).squaredNorm() < spacing * spacing;
    });
    if (apart) best = static_cast<int>(v);
  }
  return best;
}

/// The length of a closed loop of vertices.
double loop_length(const TriangleSoup& soup, const std::vector<int>& loop) {
  double length = 0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    length += (soup.points[static_cast<std::size_t>(loop[(i + 1) % loop.size()])] -
               soup.points[static_cast<std::size_t>(loop[i])])
                  .norm();
  return length;
}

/// Four vertices of the closed `loop` a quarter of its length apart along it, the
/// first `start` (each the vertex nearest its quarter).
std::array<int, 4> quarter_points(const TriangleSoup& soup, const std::vector<int>& loop, int start) {
  const std::size_t n = loop.size();
  const std::size_t first =
      static_cast<std::size_t>(std::find(loop.begin(), loop.end(), start) - loop.begin());
  const double length = loop_length(soup, loop);
  std::array<int, 4> out{start, start, start, start};
  std::array<double, 4> off{0, length, length, length};  // how far each pick is from its quarter
  double along = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    const int v = loop[(first + i) % n];
    for (std::size_t k = 1; k < 4; ++k)
      if (const double d = std::abs(along - 0.25 * static_cast<double>(k) * length); d < off[k]) {
        off[k] = d;
        out[k] = v;
      }
    const int next = loop[(first + i + 1) % n];
    along += (soup.points[static_cast<std::size_t>(next)] - soup.points[static_cast<std::size_t>(v)]).norm();
  }
  return out;
}

/// The vertex of `hole` a quarter of a quarter of its length (45 degrees round
/// it) on from its vertex nearest the loops `facing` marks: the lattice follows
/// the nearest boundary, and a square hole on it has its corners at 45 degrees to
/// that boundary's normal.
int square_start(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<int>& hole,
                 const std::vector<char>& facing) {
  int nearest = hole.front();
  double best = std::numeric_limits<double>::infinity();
  for (int v : hole)
    for (std::size_t l = 0; l < adjacency.boundary_loops.size(); ++l) {
      if (!facing[l]) continue;
      for (int w : adjacency.boundary_loops[l])
        if (const double d = (soup.points[static_cast<std::size_t>(v)] - soup.points[static_cast<std::size_t>(w)]).squaredNorm();
            d < best) {
          best = d;
          nearest = v;
        }
    }
  const std::size_t n = hole.size();
  const std::size_t first = static_cast<std::size_t>(std::find(hole.begin(), hole.end(), nearest) - hole.begin());
  const double eighth = loop_length(soup, hole) / 8;
  double along = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int v = hole[(first + i) % n], next = hole[(first + i + 1) % n];
    const double step = (soup.points[static_cast<std::size_t>(next)] - soup.points[static_cast<std::size_t>(v)]).norm();
    if (along + step / 2 >= eighth) return v;
    along += step;
  }
  return nearest;
}

/// Where the corners leave more valence-5 cones than allowed (`crowded`: a
/// hexagonal flange with a bore and six bolt holes, 24 for its holes and 6 for its
/// corners), every hole without corners at most options.square_hole_max_length
/// quads round (and shorter than the longest loop) made a square on the lattice:
/// four boundary cones (straight points in three quads) a quarter of the hole
/// apart, each taking a quarter turn from the interior. Returns the quarter turns
/// taken. (Only as many as the bound needs, shortest first, left the flange 24
/// interior cones, 94% in the band and 4.1 degrees; every such hole, 6 cones, 99%
/// and 2.7 degrees.)
int square_crowded_holes(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, double size, bool crowded,
                         const ConePlacementOptions& options, std::vector<Cone>& cones) {
  if (!crowded || adjacency.boundary_loops.size() < 2) return 0;
  std::vector<char> cornered(adjacency.boundary_loops.size(), 0);
  for (const Cone& c : cones) {
    const int loop = adjacency.loop_of_vertex[static_cast<std::size_t>(c.vertex)];
    if (loop >= 0) cornered[static_cast<std::size_t>(loop)] = 1;
  }
  std::vector<double> lengths;
  for (const std::vector<int>& loop : adjacency.boundary_loops) lengths.push_back(loop_length(soup, loop));
  const double longest = *std::max_element(lengths.begin(), lengths.end());
  // the loops with corners or too long to be squares: the lattice's frame (holes
  // too short for four cones are neither)
  std::vector<char> frame(lengths.size(), 0);
  for (std::size_t l = 0; l < lengths.size(); ++l)
    frame[l] = cornered[l] || lengths[l] >= longest || lengths[l] > options.square_hole_max_length * size;
  int taken = 0;
  for (std::size_t l = 0; l < lengths.size(); ++l) {
    if (frame[l] || lengths[l] < 4 * options.boundary_cone_spacing * size) continue;
    std::vector<char> facing = frame;  // the frame's loops, or every other loop
    if (!options.squares_face_frame) {
      std::fill(facing.begin(), facing.end(), 1);
      facing[l] = 0;
    }
    const std::vector<int>& hole = adjacency.boundary_loops[l];
    for (int v : quarter_points(soup, hole, square_start(soup, adjacency, hole, facing))) cones.push_back({v, 3});
    taken += 4;
  }
  return taken;
}

/// Valence-5 and valence-3 cones in pairs (Gauss-Bonnet kept), at the highest and
/// the lowest u among the vertices that may take a cone, while the metric's quad
/// size leaves the band: less than options.pair_band_goal of the area within
/// [0.5, 2] h, or somewhere above options.pair_largest x h (method.md section 11:
/// protrusion tips and the ends of arms get the valence-3 cones). Where the quads
/// are above pair_largest x h in a region off the boundary that lacks two quarter
/// turns or more (protrusion_caps.h: an ear, a stub), that many pairs at once, each
/// valence-3 cone at the lowest u in the region as the earlier ones leave it, and
/// those cones pinned: `settle(set, pinned)` moves the others. Each step is
/// weighed after `settle` has moved the cones (loops aligned, sizes evened); the
/// best set is kept, after options.pair_patience steps that do not better it (none
/// once it has options.pair_patience_below of the area in the band); at most
/// `room` cones are added. The sizes
/// are judged as relax_cones_for_size judges them (`tip_size`).
template <class Settle>
void add_cone_pairs(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const ConeMetricSolver& solver,
                    const std::vector<double>& curvature, const std::vector<double>& area,
                    const std::vector<char>& eligible, double spacing, double boundary_room, double size,
                    double tip_size, const Settle& settle, const ConePlacementOptions& options, int room, std::vector<char> pinned,
                    std::vector<Cone>& cones) {
  auto measure = [&](const std::vector<Cone>& set, Eigen::VectorXd& u) {
    u = solver.solve(target_curvature(adjacency, quads_per_vertex(adjacency, set)), curvature, tip_size);
    std::vector<char> mark(area.size(), 0);
    for (const Cone& c : set) mark[static_cast<std::size_t>(c.vertex)] = 1;
    return metric_band(u, area, mark);
  };
  // a vertex may take a cone when eligible and `spacing` from every interior cone
  auto free_vertices = [&](const std::vector<Cone>& set) {
    std::vector<char> free = eligible;
    for (const Cone& c : set)
      if (!adjacency.boundary_vertex[static_cast<std::size_t>(c.vertex)])
        mark_within(soup.points, soup.points[static_cast<std::size_t>(c.vertex)], spacing, 0, free);
    return free;
  };
  // up to `count` pairs into `set` (whose metric is `set_u`), the valence-3 cones in
  // `region` at its lowest u (each pair's metric solved before the next), pinned;
  // returns the cones added
  auto add_cap = [&](const std::vector<int>& region, int count, Eigen::VectorXd set_u, std::vector<Cone>& set,
                     std::vector<char>& pin) {
    int added = 0;
    for (int k = 0; k < count; ++k) {
      const std::vector<char> open = free_vertices(set);
      int tip = -1, top = -1;
      for (int v : region)
        if (open[static_cast<std::size_t>(v)] && (tip < 0 || set_u[v] < set_u[tip])) tip = v;
      for (std::size_t v = 0; v < open.size(); ++v)
        if (open[v] && (top < 0 || set_u[static_cast<Eigen::Index>(v)] > set_u[top])) top = static_cast<int>(v);
      if (tip < 0 || top < 0 ||
          (soup.points[static_cast<std::size_t>(top)] - soup.points[static_cast<std::size_t>(tip)]).squaredNorm() <
              spacing * spacing)
        break;
      set.push_back({top, 5});
      set.push_back({tip, 3});
      pin[static_cast<std::size_t>(tip)] = 1;
      added += 2;
      measure(set, set_u);
    }
    return added;
  };
  Eigen::VectorXd u;
  MetricBand band = measure(cones, u);
  // the best set so far, and the steps taken since it (each one a pair or a cap
  // that did not better it)
  std::vector<Cone> best = cones;
  MetricBand best_band = band;
  int since_best = 0;
  const auto bettered = [](const MetricBand& a, const MetricBand& b) {
    return !(a.share <= b.share && a.largest >= b.largest);
  };
  while (room >= 2) {
    if (band.share >= options.pair_band_goal && band.largest <= options.pair_largest) {
      best = cones;
      break;
    }
    const std::vector<char> free = free_vertices(cones);
    int high = -1, low = -1;
    for (std::size_t v = 0; v < free.size(); ++v) {
      if (!free[v]) continue;
      const auto vi = static_cast<Eigen::Index>(v);
      if (high < 0 || u[vi] > u[high]) high = static_cast<int>(v);
      if (low < 0 || u[vi] < u[low]) low = static_cast<int>(v);
    }
    // the valence-5 one on the boundary where the interior has no room for it
    // and the quads are smaller there (boundary_cones)
    int edge = -1;
    if (options.boundary_cones) {
      edge = cramped_boundary_extreme(soup, adjacency, u, eligible, boundary_room, options.boundary_cone_spacing * size,
                                      cones);
      if (edge >= 0 && high >= 0 && u[edge] <= u[high]) edge = -1;
    }
    if ((high < 0 && edge < 0) || low < 0) break;
    const int five = edge >= 0 ? edge : high;
    const Vec3 between = soup.points[static_cast<std::size_t>(five)] - soup.points[static_cast<std::size_t>(low)];
    if (between.squaredNorm() < spacing * spacing) break;
    std::vector<Cone> trial = cones;
    std::vector<char> trial_pinned = pinned;
    // a protrusion: the quarter turns its cap lacks, all at once
    int added = 0;
    if (options.protrusion_caps && band.largest > options.pair_largest) {
      const double level = band.mean - std::log(options.pair_largest);  // quads above pair_largest x h
      const int cap = std::min(room / 2, cap_quarter_turns(soup, adjacency, curvature, u, level, low, cones));
      if (cap >= 2) added = add_cap(sublevel_region(soup, adjacency, u, low, level), cap, u, trial, trial_pinned);
    }
    if (added == 0) {
      trial.push_back(edge >= 0 ? Cone{edge, 3} : Cone{high, 5});
      trial.push_back({low, 3});
      added = 2;
    }
    settle(trial, trial_pinned);
    Eigen::VectorXd trial_u;
    const MetricBand trial_band = measure(trial, trial_u);
    if (bettered(trial_band, best_band)) {
      best = trial;
      best_band = trial_band;
      since_best = 0;
    } else if (best_band.share >= options.pair_patience_below || ++since_best > options.pair_patience) {
      break;
    }
    cones = std::move(trial);
    pinned = std::move(trial_pinned);
    u = std::move(trial_u);
    band = trial_band;
    room -= added;
  }
  cones = std::move(best);
}

/// Whether the metric `u` (its band `band`) of `cones` has quads above
/// options.pair_largest x the size in a region away from the boundary round its
/// lowest u (the largest quads: `placed` marks the cones, whose own u is the
/// discretization's) that lacks two quarter turns or more: what
/// add_cone_pairs caps with protrusion_caps.
bool uncapped_protrusion(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                         const std::vector<double>& curvature, const Eigen::VectorXd& u,
                         const MetricBand& band, const std::vector<char>& placed,
                         const ConePlacementOptions& options, const std::vector<Cone>& cones) {
  if (!(band.largest > options.pair_largest)) return false;
  int lowest = -1;
  for (std::size_t v = 0; v < placed.size(); ++v)
    if (!placed[v] && !adjacency.boundary_vertex[v] &&
        (lowest < 0 || u[static_cast<Eigen::Index>(v)] < u[lowest]))
      lowest = static_cast<int>(v);
  if (lowest < 0) return false;
  const double level =
      band.mean - std::log(options.pair_largest);  // quads above pair_largest x the size
  return u[lowest] < level &&
         cap_quarter_turns(soup, adjacency, curvature, u, level, lowest, cones) >= 2;
}

/// Per vertex, whether its distance is at least `least`.
std::vector<char> farther_than(const std::vector<double>& distance, double least) {
  std::vector<char> out(distance.size(), 0);
  for (std::size_t v = 0; v < distance.size(); ++v) out[v] = distance[v] >= least;
  return out;
}

/// The vertex nearest v (straight line) that is `eligible` and not `taken`: v
/// itself when it is; -1 when none is.
int nearest_free(const TriangleSoup& soup, const std::vector<char>& eligible, const std::vector<char>& taken, int v) {
  const Vec3& at = soup.points[static_cast<std::size_t>(v)];
  int nearest = -1;
  double nearest_distance = 0;
  for (std::size_t w = 0; w < soup.points.size(); ++w) {
    if (!eligible[w] || taken[w]) continue;
    const double d = (soup.points[w] - at).squaredNorm();
    if (nearest < 0 || d < nearest_distance) {
      nearest = static_cast<int>(w);
      nearest_distance = d;
    }
  }
  return nearest;
}

/// The interior cones of ConePlacementOptions::fillet_cones: per convex one of
/// `fillets` (fillet_corners.h), a valence-3 cone at the vertex nearest the middle
/// of its arc among those `eligible` and not `taken`, each marking the vertices
/// within `spacing` taken and itself `pinned`. Adds them to `cones`; returns the
/// quarter turns they carry.
int place_fillet_cones(const TriangleSoup& soup, const std::vector<BoundaryCorner>& fillets,
                       const std::vector<char>& eligible, double spacing, std::vector<char>& taken,
                       std::vector<char>& pinned, std::vector<Cone>& cones) {
  int carried = 0;
  for (const BoundaryCorner& fillet : fillets) {
    if (!convex_fillet(fillet)) continue;
    const int nearest = nearest_free(soup, eligible, taken, fillet.vertex);
    if (nearest < 0) continue;  // no room: the greedy placement takes its turn
    cones.push_back({nearest, 3});
    pinned[static_cast<std::size_t>(nearest)] = 1;
    taken[static_cast<std::size_t>(nearest)] = 1;
    mark_within(soup.points, soup.points[static_cast<std::size_t>(nearest)], spacing, 1, taken);
    ++carried;
  }
  return carried;
}

/// The cones' curvature, and `deficit` quarter turns more spread over the
/// interior by area.
std::vector<double> spread_targets(const SurfaceAdjacency& adjacency, const std::vector<int>& quads,
                                   const std::vector<double>& area, double interior_area, int deficit) {
  std::vector<double> target = target_curvature(adjacency, quads);
  for (std::size_t v = 0; v < target.size(); ++v)
    if (!adjacency.boundary_vertex[v]) target[v] += deficit * quarter_turn * area[v] / interior_area;
  return target;
}

}  // namespace

std::vector<Cone> corner_cones(const TriangleSoup& soup, double size, const ConePlacementOptions& options) {
  QM_ASSERT(size > 0);
  std::vector<Cone> cones;
  for (const BoundaryCorner& c : boundary_corners(soup, corner_window_quads * size, options.corner_angle_deg)) {
    const int q = corner_quads_wanted(c.angle_deg);
    if (q != 2) cones.push_back({c.vertex, q});
  }
  return cones;
}

std::vector<Cone> place_cones(const ConeMetricSolver& solver, double size, const ConePlacementOptions& options) {
  QM_ASSERT(size > 0);
  const TriangleSoup& soup = solver.soup();
  const SurfaceAdjacency& adjacency = solver.adjacency();
  std::vector<Cone> cones = corner_cones(soup, size, options);
  const double tip_size = options.tip_sizes ? size : 0.0;  // the sizes' (tip_scale.h)
  int deficit = 4 * euler_characteristic(adjacency);
  for (const Cone& c : cones) deficit -= 2 - c.quads;
  const std::vector<double> area = vertex_areas(soup);
  // a quad mesh with more interior singular vertices than that is not what auto
  // is for (issue 18's bound): refused before any solve when the corners leave
  // more (the corners themselves are as many as the boundary has at the quad
  // scale: boundary_corners), unless small holes take the excess as squares
  double total_area = 0;
  for (double a : area) total_area += a;
  const double allowed = std::max(options.max_interior_cones, options.max_interior_cone_share * total_area / (size * size));
  // the fillets' valence-3 cones (fillet_cones) each ask one valence-5 cone more:
  // counted in the crowding (a plate with rounded corners and six holes: 20 quarter
  // turns for the holes, 4 fillets, 28 interior cones for 24 allowed, and every
  // fillet placement was refused)
  const bool greedy = options.interior == InteriorCones::greedy;
  const std::vector<BoundaryCorner> fillets =
      greedy && options.fillet_cones ? fillet_corners(soup, size) : std::vector<BoundaryCorner>{};
  const auto fillet_cone_count = std::count_if(fillets.begin(), fillets.end(), convex_fillet);
  if (options.square_crowded_holes && deficit < 0)
    deficit += square_crowded_holes(soup, adjacency, size,
                                    options.square_every_hole || -deficit + 2 * fillet_cone_count > allowed, options,
                                    cones);
  // the cones on the boundary (the corners, then any boundary cones) come first;
  // the interior ones, which the settling moves, after them
  const std::size_t corners_only = cones.size();
  std::size_t corner_count = corners_only;
  if (greedy && deficit == 0 && !(options.pair_band_goal > 0)) return cones;

  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  if (std::abs(deficit) > allowed)
    throw Error(ErrorCode::unsupported,
                fmt::format("the {} corners leave {} quarter turns to interior cones, more than the {:.0f} allowed "
                            "(max({:g}, {:g}% of the quads))",
                            cones.size(), std::abs(deficit), allowed, options.max_interior_cones,
                            100 * options.max_interior_cone_share));
  const std::vector<double> distance = distance_to_boundary(soup, adjacency);
  double boundary_distance = options.boundary_distance;
  // the vertices that may take an interior cone: this far from the boundary, and
  // not where the placement is asked to avoid
  const auto eligible_beyond = [&](double from_boundary) {
    std::vector<char> out = farther_than(distance, from_boundary);
    for (const Vec3& avoided : options.avoided_points)
      mark_within(soup.points, avoided, options.avoided_radius * size, 0, out);
    return out;
  };
  std::vector<char> eligible = eligible_beyond(boundary_distance * size);
  double interior_area = 0;
  for (std::size_t v = 0; v < area.size(); ++v)
    if (!adjacency.boundary_vertex[v]) interior_area += area[v];
  // with boundary_cones, a boundary vertex may take a cone where no eligible
  // vertex is this near it along the edges
  const auto boundary_room = [&] { return (boundary_distance + 1) * size; };
  std::vector<char> taken(soup.points.size(), 0);
  // vertices nearer than cone_spacing quads to a placed interior cone are taken
  // too: two cones closer than that compete for the same lattice cells
  double cone_spacing = options.cone_spacing;
  double spacing = cone_spacing * size;
  // the turns the cones steer: the boundary loops' and, on a surface with
  // handles, the handles' (cross_field.h LoopTurns)
  const LoopTurns model = adjacency.boundary_loops.size() > 1 || (has_handles(adjacency) && options.steer_handles)
                              ? loop_turns(soup, adjacency, solver, options.steer_handles)
                              : LoopTurns{};
  const bool steered = model.steers();
  if (!greedy) {
    // the field's singularities, all at once; they carry what the corners leave
    // when the field meets every corner as corner_cones counts it
    CrossFieldOptions field_options;
    field_options.length = size;
    field_options.boundary_quads = quads_per_vertex(adjacency, cones);
    const std::vector<Cone> singular = field_singularities(smooth_cross_field(soup, adjacency, field_options));
    int carried = 0;
    for (const Cone& c : singular) carried += 4 - c.quads;
    if (carried != deficit)
      throw Error(ErrorCode::unsupported,
                  fmt::format("the cross field's {} singularities carry {} quarter turns where the {} corners leave {}",
                              singular.size(), carried, cones.size(), deficit));
    if (static_cast<double>(singular.size()) > allowed)
      throw Error(ErrorCode::unsupported,
                  fmt::format("the cross field has {} singularities, more than the {:.0f} cones allowed",
                              singular.size(), allowed));
    // each as near where the field puts it as field_boundary_distance quads from
    // the boundary and field_cone_spacing from the others allow
    const std::vector<char> field_eligible = eligible_beyond(options.field_boundary_distance * size);
    const double field_spacing = options.field_cone_spacing * size;
    for (Cone c : singular) {
      c.vertex = nearest_free(soup, field_eligible, taken, c.vertex);
      if (c.vertex < 0)
        throw Error(ErrorCode::unsupported,
                    fmt::format("no inner vertex is {:g} quads from the boundary and {:g} from the other cones to "
                                "take the cross field's singularities",
                                options.field_boundary_distance, options.field_cone_spacing));
      cones.push_back(c);
      taken[static_cast<std::size_t>(c.vertex)] = 1;
      mark_within(soup.points, soup.points[static_cast<std::size_t>(c.vertex)], field_spacing, 1, taken);
    }
    deficit = 0;
  }
  // the fillets' cones first, kept where they are (`pinned`)
  std::vector<char> pinned(soup.points.size(), 0);
  if (greedy && options.fillet_cones) {
    const int before = static_cast<int>(cones.size());
    deficit -= place_fillet_cones(soup, fillets, eligible, spacing, taken, pinned, cones);
    const int placed = static_cast<int>(cones.size()) - before;
    if (placed + std::abs(deficit) > allowed)
      throw Error(ErrorCode::unsupported,
                  fmt::format("the {} fillets' cones and the {} quarter turns the corners leave after them are more "
                              "than the {:.0f} interior cones allowed",
                              placed, std::abs(deficit), allowed));
  }
  const int step = deficit > 0 ? 1 : -1;  // valence 3 (+1 quarter turn) or 5 (-1)
  while (deficit != 0) {
    // the cones so far, the rest spread over the interior by area
    const std::vector<int> quads = quads_per_vertex(adjacency, cones);
    const Eigen::VectorXd u =
        solver.solve(spread_targets(adjacency, quads, area, interior_area, deficit), curvature, tip_size);
    int extreme = -1;
    for (std::size_t v = 0; v < soup.points.size(); ++v)
      if (eligible[v] && !taken[v] && (extreme < 0 || step * u[static_cast<Eigen::Index>(v)] < step * u[extreme]))
        extreme = static_cast<int>(v);
    if (step < 0 && options.boundary_cones) {
      // where no interior vertex near the boundary may take the cone (a hole in a
      // shaft a few quads wide), on the boundary when the quads are smaller there
      const int edge = cramped_boundary_extreme(soup, adjacency, u, eligible, boundary_room(),
                                                options.boundary_cone_spacing * size, cones);
      if (edge >= 0 && (extreme < 0 || u[edge] > u[extreme])) {
        // on a hole a few quads round with no cone yet, four a quarter of its
        // length apart: the hole a square on the lattice, its quarter turns taken
        // where they are
        std::vector<int> on_boundary{edge};
        const int loop = adjacency.loop_of_vertex[static_cast<std::size_t>(edge)];
        const std::vector<int>& vertices = adjacency.boundary_loops[static_cast<std::size_t>(loop)];
        const double length = loop_length(soup, vertices);
        const bool bare = std::none_of(cones.begin(), cones.end(), [&](const Cone& c) {
          return std::find(vertices.begin(), vertices.end(), c.vertex) != vertices.end();
        });
        if (deficit <= -4 && bare && length <= options.square_hole_length * size &&
            length >= 4 * options.boundary_cone_spacing * size) {
          const std::array<int, 4> quarters = quarter_points(soup, vertices, edge);
          on_boundary.assign(quarters.begin(), quarters.end());
        }
        for (int b : on_boundary) {
          cones.insert(cones.begin() + static_cast<std::ptrdiff_t>(corner_count), Cone{b, 3});
          ++corner_count;
          mark_within(soup.points, soup.points[static_cast<std::size_t>(b)], spacing, 1, taken);
          deficit -= step;
        }
        continue;
      }
    }
    if (extreme < 0 && boundary_distance > options.narrow_boundary_distance) {
      // a part too narrow for the cones this far from its boundary (a shaft, the
      // ring round a bore): the rest of them, and any pairs, may come nearer
      boundary_distance = options.narrow_boundary_distance;
      cone_spacing = std::min(cone_spacing, options.narrow_cone_spacing);
      spacing = cone_spacing * size;
      eligible = eligible_beyond(boundary_distance * size);
      std::fill(taken.begin(), taken.end(), 0);
      for (std::size_t c = corners_only; c < cones.size(); ++c)
        mark_within(soup.points, soup.points[static_cast<std::size_t>(cones[c].vertex)], spacing, 1, taken);
      continue;
    }
    if (extreme < 0)
      throw Error(ErrorCode::unsupported,
                  fmt::format("no inner vertex is {:g} quads from the boundary and {:g} from the other cones to take "
                              "a cone ({} of {} placed)",
                              boundary_distance, cone_spacing, cones.size(), cones.size() + std::abs(deficit)));
    int best = extreme;
    if (steered) {
      // among the vertices nearly as extreme, the one after which the field meets
      // the loops closest to whole quarter turns (the rest of D still spread)
      const std::vector<double> next = spread_targets(adjacency, quads, area, interior_area, deficit - step);
      Eigen::VectorXd rhs(u.size());
      for (Eigen::Index v = 0; v < rhs.size(); ++v) rhs[v] = next[static_cast<std::size_t>(v)] - curvature[static_cast<std::size_t>(v)];
      double best_cost = -1;
      for (std::size_t v = 0; v < soup.points.size(); ++v) {
        const auto vi = static_cast<Eigen::Index>(v);
        if (!eligible[v] || taken[v] || step * (u[vi] - u[extreme]) > options.extreme_tolerance) continue;
        double cost = 0;
        for (std::size_t l = 0; l < model.rows(); ++l)
          if (static_cast<int>(l) != model.reference)
            cost += std::abs(quarter_turn_remainder(model.offset[l] - model.gradient[l].dot(rhs) -
                                                    step * quarter_turn * model.gradient[l][vi]));
        if (best_cost < 0 || cost < best_cost) {
          best_cost = cost;
          best = static_cast<int>(v);
        }
      }
    }
    cones.push_back({best, 4 - step});
    taken[static_cast<std::size_t>(best)] = 1;
    mark_within(soup.points, soup.points[static_cast<std::size_t>(best)], spacing, 1, taken);
    deficit -= step;
  }
  // the cones moved to align the loops, then to even the quad sizes; those at
  // `pinned` vertices (a protrusion's cap) stay; none comes nearer another than
  // the narrow parts' spacing
  const double closest = options.narrow_cone_spacing * size;
  const auto settle = [&](std::vector<Cone>& set, const std::vector<char>& held) {
    if (set.size() == corner_count) return;
    if (steered)
      align_loops_by_cones(soup, adjacency, model, curvature, eligible, held, options.alignment_rings,
                           options.cone_separation, closest, set);
    if (greedy && options.size_relaxation_passes > 0) {
      relax_cones_for_size(soup, adjacency, solver, model, curvature, area, eligible, held,
                           options.cone_separation, closest, options.size_relaxation_passes,
                           options.relaxation_alignment_slack, tip_size, set);
      if (steered)
        align_loops_by_cones(soup, adjacency, model, curvature, eligible, held, options.alignment_rings,
                             options.cone_separation, closest, set);
    }
  };
  // (not the field's singularities: each loop already turns whole quarter turns in
  // the field, and the moves away from where it put them spread the sizes; the
  // spanner's: from 100% of the quads in the size band to 5% of the area)
  if (greedy) settle(cones, pinned);
  if (greedy && options.pair_band_goal > 0) {
    const int interior = static_cast<int>(cones.size() - corner_count);
    add_cone_pairs(soup, adjacency, solver, curvature, area, eligible, spacing, boundary_room(), size, tip_size, settle,
                   options, static_cast<int>(allowed) - interior, pinned, cones);
  }
  if (options.min_metric_band > 0 || options.mapped_metric_band > 0 || options.max_metric_largest > 0) {
    std::vector<char> placed(area.size(), 0);
    for (const Cone& c : cones) placed[static_cast<std::size_t>(c.vertex)] = 1;
    const Eigen::VectorXd u =
        solver.solve(target_curvature(adjacency, quads_per_vertex(adjacency, cones)), curvature, tip_size);
    const MetricBand band = metric_band(u, area, placed);
    // the largest a quad at a time (half a quad round each vertex)
    const double largest = options.max_metric_largest > 0
                               ? quad_scale_largest(soup, adjacency, u, area, placed, band.mean, 0.5 * size)
                               : band.largest;
    const auto leave = [&] {
      return fmt::format("the {} cones leave {:.0f}% of the area with quads within [0.5, 2] x the size", cones.size(),
                         100 * band.share);
    };
    if (band.share < options.min_metric_band ||
        (options.max_metric_largest > 0 && largest > options.max_metric_largest)) {
      const std::string refusal = leave() + fmt::format(" (up to {:.0f} x): not mapped", largest);
      if (!options.protrusion_caps && greedy &&
          uncapped_protrusion(soup, adjacency, curvature, u, band, placed, options, cones))
        throw UncappedProtrusion(ErrorCode::unsupported,
                                 refusal + " (a protrusion's cap lacks its cones)");
      throw Error(ErrorCode::unsupported, refusal);
    }
    if (band.share < options.mapped_metric_band)
      throw Error(ErrorCode::unsupported, leave() + ": not mapped (their quads would miss the band)");
  }
  return cones;
}

std::vector<Cone> place_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, double size,
                              const ConePlacementOptions& options) {
  // (factored at its first solve: a placement that needs none costs none)
  const ConeMetricSolver solver(soup, adjacency);
  return place_cones(solver, size, options);
}

}  // namespace qm
