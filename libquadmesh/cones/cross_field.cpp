#include "libquadmesh/cones/cross_field.h"

#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/cones/handle_alignment.h"
#include "libquadmesh/cones/internal/face_geometry.h"
#include "libquadmesh/cones/loop_alignment.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>

namespace qm {

namespace {

/// A frame within this of a whole quarter turn (radians) counts as aligned: as a
/// seam does (cone_map.cpp). The loop's turn is the metric's solve, whose round-off
/// grows with u: on a fine scan whose ears' u reaches -8 a loop came out turned by
/// 1e-5 (bunny-open-large, 0.0006 degrees) and its placement was refused unmapped.
constexpr double alignment_tolerance = 1e-4;

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

namespace {

/// What the propagation needs of every triangle.
struct LocalFrames {
  std::vector<CornerValues> corners;
  std::vector<std::array<double, 3>> cot;
};

/// The extra rotation (radians) crossing side k of triangle f into its twin.
using ExtraTurn = std::function<double(std::size_t f, const EdgeCorner& g)>;

/// The angle a direction at `angle` in f gets in the twin g across side k of f.
double transported(const TriangleSoup& soup, const LocalFrames& frames, const Eigen::VectorXd& u, std::size_t f, int k,
                   const EdgeCorner& g, double angle, const ExtraTurn& extra) {
  const Triangle& t = soup.triangles[f];
  const auto gf = static_cast<std::size_t>(g.face);
  // side k is a->b in f; g holds b->a with b at corner g.i, a at corner g.j
  const double in_f = side_angle(frames.corners[f], k);
  const double in_g = std::arg(frames.corners[gf][static_cast<std::size_t>(g.i)] - frames.corners[gf][static_cast<std::size_t>(g.j)]);
  const double turn = conformal_rotation(frames.cot[f][static_cast<std::size_t>((k + 2) % 3)],
                                         frames.cot[gf][static_cast<std::size_t>(3 - g.i - g.j)], u[t[k]],
                                         u[t[(k + 1) % 3]]);
  return angle - in_f + in_g + turn + extra(f, g);
}

/// The breadth-first tree propagate() walks (the same for every extra turn):
/// the triangles in the order reached, and per triangle the one it was reached
/// from with that one's side (-1, -1 for the seed).
struct FieldTree {
  std::vector<int> order;
  std::vector<std::pair<int, int>> parent;
};

/// Angles along a breadth-first tree of the triangles from `seed` (at
/// `seed_angle`); marks the tree's sides and returns the tree.
FieldTree propagate(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const LocalFrames& frames,
                    const Eigen::VectorXd& u, int seed, double seed_angle, const ExtraTurn& extra, CrossField& field) {
  const std::size_t nF = soup.triangles.size();
  FieldTree tree;
  tree.parent.assign(nF, {-1, -1});
  tree.order.push_back(seed);
  field.angle.assign(nF, 0.0);
  field.tree_side.assign(nF, {0, 0, 0});
  field.angle[static_cast<std::size_t>(seed)] = seed_angle;
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
      field.angle[gf] = transported(soup, frames, u, f, k, g, field.angle[f], extra);
      field.tree_side[f][static_cast<std::size_t>(k)] = 1;
      field.tree_side[gf][static_cast<std::size_t>(g.i)] = 1;  // g's side from b (corner g.i) to a
      tree.parent[gf] = {static_cast<int>(f), k};
      tree.order.push_back(g.face);
      queue.push(g.face);
    }
  }
  return tree;
}

/// Quarter turns across inner sides, axes of boundary sides, misalignments; and
/// per boundary loop the remainder of its first side's offset from the frame (and,
/// if asked, that side's triangle and the offset itself).
std::vector<double> classify_sides(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                   const LocalFrames& frames, const Eigen::VectorXd& u, const ExtraTurn& extra,
                                   CrossField& field, std::vector<std::pair<int, double>>* first_side = nullptr) {
  const std::size_t nF = soup.triangles.size();
  field.quarter_turns.assign(nF, {0, 0, 0});
  field.boundary_axis.assign(nF, {-1, -1, -1});
  field.max_misalignment = 0;
  field.max_seam_misalignment = 0;
  field.misaligned_loop = -1;
  std::vector<double> loop_offset(adjacency.boundary_loops.size(), 0.0);
  std::vector<char> loop_seen(adjacency.boundary_loops.size(), 0);
  for (std::size_t f = 0; f < nF; ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const EdgeCorner g = adjacency.find(t[(k + 1) % 3], t[k]);
      if (g.face < 0) {
        const double offset = side_angle(frames.corners[f], k) - field.angle[f];
        const double miss = std::abs(quarter_turn_remainder(offset));
        const auto loop = static_cast<std::size_t>(adjacency.loop_of_vertex[static_cast<std::size_t>(t[k])]);
        field.boundary_axis[f][static_cast<std::size_t>(k)] = modulo4(whole_quarter_turns(offset)) % 2;
        if (!loop_seen[loop]++) {
          loop_offset[loop] = quarter_turn_remainder(offset);
          if (first_side) (*first_side)[loop] = {static_cast<int>(f), offset};
        }
        field.max_misalignment = std::max(field.max_misalignment, miss);
        if (miss > alignment_tolerance && field.misaligned_loop < 0) field.misaligned_loop = static_cast<int>(loop);
        continue;
      }
      const double jump = field.angle[static_cast<std::size_t>(g.face)] -
                          transported(soup, frames, u, f, k, g, field.angle[f], extra);
      field.max_misalignment = std::max(field.max_misalignment, std::abs(quarter_turn_remainder(jump)));
      field.max_seam_misalignment = std::max(field.max_seam_misalignment, std::abs(quarter_turn_remainder(jump)));
      // g's frame is f's transported frame turned by jump = r quarter turns; the
      // charts W = e^(-i angle) x then differ by i^(-r)
      field.quarter_turns[f][static_cast<std::size_t>(k)] = modulo4(-whole_quarter_turns(jump));
    }
  }
  return loop_offset;
}

LocalFrames local_frames(const TriangleSoup& soup) {
  const std::size_t nF = soup.triangles.size();
  LocalFrames frames;
  frames.corners.resize(nF);
  frames.cot.resize(nF);
  for (std::size_t f = 0; f < nF; ++f) {
    frames.corners[f] = local_corners(soup, f);
    frames.cot[f] = corner_cotangents(soup, f);
  }
  return frames;
}

/// Per triangle, the sum of `turn` along the field's tree from its seed.
std::vector<double> tree_integral(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FieldTree& tree,
                                  const ExtraTurn& turn) {
  std::vector<double> sum(soup.triangles.size(), 0.0);
  for (int f : tree.order) {
    const auto [p, k] = tree.parent[static_cast<std::size_t>(f)];
    if (p < 0) continue;  // the seed
    const Triangle& t = soup.triangles[static_cast<std::size_t>(p)];
    sum[static_cast<std::size_t>(f)] =
        sum[static_cast<std::size_t>(p)] + turn(static_cast<std::size_t>(p), adjacency.find(t[(k + 1) % 3], t[k]));
  }
  return sum;
}

/// The turn of a SideForm crossing from f into g.
ExtraTurn side_form_turn(const SideForm& form) {
  return [&form](std::size_t, const EdgeCorner& g) {
    return -form[static_cast<std::size_t>(g.face)][static_cast<std::size_t>(g.i)];
  };
}

/// The coefficient of each handle form that makes the field, as propagated with no
/// extra turn, close around every handle. Across an inner edge the tree does not
/// cross, the field jumps by J (the holonomy of the edge's loop through the tree);
/// adding sum_k c_k form_k lowers J by sum_k c_k P_k, P_k the form's period along
/// that loop (an intersection number). The loops whose periods are independent
/// (fewest crossings first) give the square system sum_k c_k P_k = remainder(J).
/// A loop round a handle: the tree's paths from the seed to the two triangles of
/// an inner side the tree does not cross (side k of f, into g), closed by it.
struct HandleLoop {
  std::size_t f = 0;
  int k = 0;
  EdgeCorner g;
  Eigen::VectorXd period;  ///< per handle form, its period along the loop
  double crossings = 0;
};

/// The loops whose periods are independent, fewest crossings first (as many as
/// there are forms, or fewer).
std::vector<HandleLoop> independent_handle_loops(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                                 const FieldTree& tree, const std::vector<SideForm>& forms,
                                                 const CrossField& field) {
  const std::size_t m = forms.size();
  std::vector<std::vector<double>> integral;
  for (const SideForm& form : forms) integral.push_back(tree_integral(soup, adjacency, tree, side_form_turn(form)));
  std::vector<HandleLoop> loops;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const EdgeCorner g = adjacency.find(t[(k + 1) % 3], t[k]);
      if (g.face < static_cast<int>(f) || field.tree_side[f][static_cast<std::size_t>(k)]) continue;
      HandleLoop loop{f, k, g, Eigen::VectorXd(static_cast<Eigen::Index>(m)), 0.0};
      for (std::size_t c = 0; c < m; ++c) {
        const double p = integral[c][f] + side_form_turn(forms[c])(f, g) - integral[c][static_cast<std::size_t>(g.face)];
        loop.period[static_cast<Eigen::Index>(c)] = std::round(p);
        loop.crossings += std::abs(std::round(p));
      }
      if (loop.crossings == 0) continue;
      loops.push_back(std::move(loop));
    }
  }
  std::stable_sort(loops.begin(), loops.end(),
                   [](const HandleLoop& a, const HandleLoop& b) { return a.crossings < b.crossings; });
  // independent periods by Gram-Schmidt
  std::vector<Eigen::VectorXd> basis;
  std::vector<HandleLoop> chosen;
  for (const HandleLoop& loop : loops) {
    if (chosen.size() == m) break;
    Eigen::VectorXd r = loop.period;
    for (const Eigen::VectorXd& b : basis) r -= r.dot(b) * b;
    if (r.norm() < 1e-6) continue;
    basis.push_back(r / r.norm());
    chosen.push_back(loop);
  }
  return chosen;
}

/// The field's jump across the side that closes `loop` (radians; its remainder to
/// a whole quarter turn is the loop's holonomy).
double handle_jump(const TriangleSoup& soup, const LocalFrames& frames, const Eigen::VectorXd& u,
                   const CrossField& field, const HandleLoop& loop) {
  const ExtraTurn none = [](std::size_t, const EdgeCorner&) { return 0.0; };
  return field.angle[static_cast<std::size_t>(loop.g.face)] -
         transported(soup, frames, u, loop.f, loop.k, loop.g, field.angle[loop.f], none);
}

std::vector<double> handle_coefficients(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                        const LocalFrames& frames, const Eigen::VectorXd& u, const FieldTree& tree,
                                        const std::vector<SideForm>& forms, const CrossField& field) {
  const std::size_t m = forms.size();
  const std::vector<HandleLoop> chosen = independent_handle_loops(soup, adjacency, tree, forms, field);
  std::vector<double> c(m, 0.0);
  if (chosen.empty()) return c;
  Eigen::MatrixXd A(static_cast<Eigen::Index>(chosen.size()), static_cast<Eigen::Index>(m));
  Eigen::VectorXd b(static_cast<Eigen::Index>(chosen.size()));
  for (std::size_t r = 0; r < chosen.size(); ++r) {
    A.row(static_cast<Eigen::Index>(r)) = chosen[r].period.transpose();
    b[static_cast<Eigen::Index>(r)] = quarter_turn_remainder(handle_jump(soup, frames, u, field, chosen[r]));
  }
  const Eigen::VectorXd solution = A.completeOrthogonalDecomposition().solve(b);
  for (std::size_t k = 0; k < m; ++k) c[k] = solution[static_cast<Eigen::Index>(k)];
  return c;
}

}  // namespace

double LoopTurns::turn(int loop, const Eigen::VectorXd& rhs) const {
  if (loop == reference) return 0.0;
  return quarter_turn_remainder(offset[static_cast<std::size_t>(loop)] -
                                gradient[static_cast<std::size_t>(loop)].dot(rhs));
}

LoopTurns loop_turns(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const ConeMetricSolver& solver,
                     bool with_handles) {
  const LocalFrames frames = local_frames(soup);
  const auto [seed, seed_side] = seed_triangle(soup, adjacency);
  QM_ASSERT(seed_side >= 0);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(soup.points.size()));
  const ExtraTurn none = [](std::size_t, const EdgeCorner&) { return 0.0; };
  CrossField field;
  const FieldTree tree = propagate(soup, adjacency, frames, zero, seed,
                                   side_angle(frames.corners[static_cast<std::size_t>(seed)], seed_side), none, field);
  std::vector<std::pair<int, double>> first_side(adjacency.boundary_loops.size(), {-1, 0.0});
  classify_sides(soup, adjacency, frames, zero, none, field, &first_side);
  const auto side_weight = [&](std::size_t f, int k, const EdgeCorner& g) {
    return 0.5 * (frames.cot[f][static_cast<std::size_t>((k + 2) % 3)] +
                  frames.cot[static_cast<std::size_t>(g.face)][static_cast<std::size_t>(3 - g.i - g.j)]);
  };
  // adds sign times the turns w_ab (u_b - u_a) of the tree's edges from the seed
  // to f, as coefficients of u
  const auto add_path = [&](int f, double sign, Eigen::VectorXd& c) {
    while (tree.parent[static_cast<std::size_t>(f)].first >= 0) {
      const auto [p, k] = tree.parent[static_cast<std::size_t>(f)];
      const Triangle& t = soup.triangles[static_cast<std::size_t>(p)];
      const EdgeCorner g = adjacency.find(t[(k + 1) % 3], t[k]);
      const double w = side_weight(static_cast<std::size_t>(p), k, g);
      c[t[(k + 1) % 3]] += sign * w;
      c[t[k]] -= sign * w;
      f = p;
    }
  };
  LoopTurns turns;
  turns.reference = adjacency.loop_of_vertex[static_cast<std::size_t>(soup.triangles[static_cast<std::size_t>(seed)][static_cast<std::size_t>(seed_side)])];
  turns.offset.assign(adjacency.boundary_loops.size(), 0.0);
  turns.gradient.resize(adjacency.boundary_loops.size());
  for (std::size_t l = 0; l < adjacency.boundary_loops.size(); ++l) {
    if (static_cast<int>(l) == turns.reference) continue;
    turns.offset[l] = first_side[l].second;
    // the offset falls by the turn w_ab (u_b - u_a) of every tree edge on the way
    Eigen::VectorXd along = Eigen::VectorXd::Zero(zero.size());
    add_path(first_side[l].first, 1.0, along);
    turns.gradient[l] = solver.apply_inverse(along);
  }
  if (!with_handles || !has_handles(adjacency)) return turns;
  // the handles: around each independent loop the field jumps by J(0) + c . u,
  // c the sum of the tree's w_ab (e_b - e_a) from the seed to g, less that to f,
  // less the closing side's; a row turn = remainder(offset - gradient . rhs) with
  // offset J(0) and gradient -L^-1 c (the field and its tree as above: u = 0)
  const std::vector<SideForm> forms = handle_forms(soup, adjacency);
  if (forms.empty()) return turns;
  for (const HandleLoop& loop : independent_handle_loops(soup, adjacency, tree, forms, field)) {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(zero.size());
    add_path(loop.g.face, 1.0, c);
    add_path(static_cast<int>(loop.f), -1.0, c);
    const Triangle& t = soup.triangles[loop.f];
    const double w = side_weight(loop.f, loop.k, loop.g);
    c[t[(loop.k + 1) % 3]] -= w;
    c[t[loop.k]] += w;
    turns.offset.push_back(handle_jump(soup, frames, zero, field, loop));
    turns.gradient.push_back(-solver.apply_inverse(c));
  }
  return turns;
}

CrossField cone_cross_field(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                            LoopPotentials* potentials) {
  QM_ASSERT(!potentials || &potentials->soup() == &soup);
  const LocalFrames frames = local_frames(soup);
  const auto [seed, seed_side] = seed_triangle(soup, adjacency);
  const double seed_angle = seed_side >= 0 ? side_angle(frames.corners[static_cast<std::size_t>(seed)], seed_side) : 0.0;
  CrossField field;
  const ExtraTurn none = [](std::size_t, const EdgeCorner&) { return 0.0; };
  const FieldTree tree = propagate(soup, adjacency, frames, u, seed, seed_angle, none, field);
  // the handles first (their forms keep every boundary loop where it is)
  // (none on a genus-0 surface: chi = 2 - 2g - loops)
  const std::vector<SideForm> handles = has_handles(adjacency) ? handle_forms(soup, adjacency) : std::vector<SideForm>{};
  SideForm handle_turn;
  ExtraTurn base = none;
  if (!handles.empty()) {
    field.handle_rotation = handle_coefficients(soup, adjacency, frames, u, tree, handles, field);
    handle_turn = combined_form(handles, field.handle_rotation);
    base = side_form_turn(handle_turn);
    propagate(soup, adjacency, frames, u, seed, seed_angle, base, field);
  }
  const std::vector<double> offset = classify_sides(soup, adjacency, frames, u, base, field);
  field.loop_rotation.assign(adjacency.boundary_loops.size(), 0.0);
  if (adjacency.boundary_loops.size() <= 1) return field;

  // the other loops: the trivial connection that turns each by its offset
  const Triangle& st = soup.triangles[static_cast<std::size_t>(seed)];
  const int reference = adjacency.loop_of_vertex[static_cast<std::size_t>(st[seed_side])];
  Eigen::MatrixXd own;
  if (!potentials) own = loop_potentials(soup, adjacency, reference);
  const Eigen::MatrixXd& phi = potentials ? (*potentials)(reference) : own;
  Eigen::VectorXd c(phi.cols());
  for (std::size_t l = 0, col = 0; l < offset.size(); ++l) {
    if (static_cast<int>(l) == reference) continue;
    field.loop_rotation[l] = offset[l];
    c[static_cast<Eigen::Index>(col++)] = offset[l];
  }
  const Eigen::VectorXd potential = phi * c;
  const ExtraTurn extra = [&](std::size_t f, const EdgeCorner& g) {
    return base(f, g) + potential[g.face] - potential[static_cast<Eigen::Index>(f)];
  };
  propagate(soup, adjacency, frames, u, seed, seed_angle, extra, field);
  classify_sides(soup, adjacency, frames, u, extra, field);
  return field;
}

}  // namespace qm
