#include "libquadmesh/cones/cross_field.h"

#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/internal/face_geometry.h"
#include "libquadmesh/core/error.h"

#include <cmath>
#include <queue>

namespace qm {

namespace {

constexpr double quarter_turn = M_PI / 2;
/// A frame within this of a whole quarter turn (radians) counts as aligned.
constexpr double alignment_tolerance = 1e-6;

/// The angle of side k (corner k to corner k + 1) of a triangle in its local frame.
double side_angle(const CornerValues& x, int k) { return std::arg(x[static_cast<std::size_t>((k + 1) % 3)] - x[static_cast<std::size_t>(k)]); }

int whole_quarter_turns(double angle) { return static_cast<int>(std::lround(angle / quarter_turn)); }

int modulo4(int q) { return ((q % 4) + 4) % 4; }

/// The first triangle with a boundary side, and that side (or triangle 0, side -1).
std::pair<int, int> seed_triangle(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) {
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Triangle& t = soup.triangles[f];
      if (adjacency.find(t[(k + 1) % 3], t[k]).face < 0) return {static_cast<int>(f), k};
    }
  return {0, -1};
}

}  // namespace

double quarter_turn_remainder(double angle) {
  return angle - quarter_turn * std::round(angle / quarter_turn);
}

CrossField cone_cross_field(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u) {
  const std::size_t nF = soup.triangles.size();
  std::vector<CornerValues> local(nF);
  std::vector<std::array<double, 3>> cot(nF);
  for (std::size_t f = 0; f < nF; ++f) {
    local[f] = local_corners(soup, f);
    cot[f] = corner_cotangents(soup, f);
  }
  CrossField field;
  field.angle.assign(nF, 0.0);
  field.quarter_turns.assign(nF, {0, 0, 0});
  field.tree_side.assign(nF, {0, 0, 0});
  field.boundary_axis.assign(nF, {-1, -1, -1});

  // the angle a direction at `angle` in f gets in the twin across side k of f
  auto transported = [&](std::size_t f, int k, const EdgeCorner& g, double angle) {
    const Triangle& t = soup.triangles[f];
    const auto gf = static_cast<std::size_t>(g.face);
    // side k is a->b in f; g holds b->a with b at corner g.i, a at corner g.j
    const double in_f = side_angle(local[f], k);
    const double in_g = std::arg(local[gf][static_cast<std::size_t>(g.i)] - local[gf][static_cast<std::size_t>(g.j)]);
    const double turn = conformal_rotation(cot[f][static_cast<std::size_t>((k + 2) % 3)],
                                           cot[gf][static_cast<std::size_t>(3 - g.i - g.j)], u[t[k]], u[t[(k + 1) % 3]]);
    return angle - in_f + in_g + turn;
  };

  const auto [seed, seed_side] = seed_triangle(soup, adjacency);
  field.angle[static_cast<std::size_t>(seed)] = seed_side >= 0 ? side_angle(local[static_cast<std::size_t>(seed)], seed_side) : 0.0;
  std::vector<char> reached(nF, 0);
  reached[static_cast<std::size_t>(seed)] = 1;
  std::queue<int> queue;
  queue.push(seed);
  while (!queue.empty()) {
    const auto f = static_cast<std::size_t>(queue.front());
    queue.pop();
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const EdgeCorner g = adjacency.find(t[(k + 1) % 3], t[k]);
      if (g.face < 0 || reached[static_cast<std::size_t>(g.face)]) continue;
      const auto gf = static_cast<std::size_t>(g.face);
      reached[gf] = 1;
      field.angle[gf] = transported(f, k, g, field.angle[f]);
      field.tree_side[f][static_cast<std::size_t>(k)] = 1;
      field.tree_side[gf][static_cast<std::size_t>(g.i)] = 1;  // g's side from b (corner g.i) to a
      queue.push(g.face);
    }
  }

  for (std::size_t f = 0; f < nF; ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const EdgeCorner g = adjacency.find(t[(k + 1) % 3], t[k]);
      if (g.face < 0) {
        const double offset = side_angle(local[f], k) - field.angle[f];
        const double miss = std::abs(quarter_turn_remainder(offset));
        field.boundary_axis[f][static_cast<std::size_t>(k)] = modulo4(whole_quarter_turns(offset)) % 2;
        if (miss > field.max_misalignment) field.max_misalignment = miss;
        if (miss > alignment_tolerance && field.misaligned_loop < 0)
          field.misaligned_loop = adjacency.loop_of_vertex[static_cast<std::size_t>(t[k])];
        continue;
      }
      const auto gf = static_cast<std::size_t>(g.face);
      const double jump = field.angle[gf] - transported(f, k, g, field.angle[f]);
      const double miss = std::abs(quarter_turn_remainder(jump));
      if (miss > field.max_misalignment) field.max_misalignment = miss;
      // g's frame is f's transported frame turned by jump = r quarter turns; the
      // charts W = e^(-i angle) x then differ by i^(-r)
      field.quarter_turns[f][static_cast<std::size_t>(k)] = modulo4(-whole_quarter_turns(jump));
    }
  }
  return field;
}

}  // namespace qm
