#include "libquadmesh/param/quantization.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>
#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>

namespace qm {

namespace {

/// Image radius (lattice units) of the disk that moves rigidly with each cone.
constexpr double disk_radius = 0.75;

/// The disk's model blends into the target from this fraction of its radius on
/// (smoothstep of (rho - blend_start) / blend_width, rho = image distance / radius).
constexpr double blend_start = 0.25;
constexpr double blend_width = 1.0 - blend_start;

/// Rule 4: a period or level farther than this from 0 (lattice units) is not rounded
/// to 0, and levels farther apart than this stay distinct.
constexpr double collapse_threshold = 0.25;

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Half the cotangent of each corner's angle: the weight of the opposite edge in
/// the Dirichlet energy of a linear function, integral |grad u|^2 = sum w_jk (u_j - u_k)^2.
std::array<double, 3> corner_weights(const TriangleSoup& soup, const Triangle& t) {
  std::array<double, 3> w{};
  for (int i = 0; i < 3; ++i) {
    const Vec3& p = soup.points[static_cast<std::size_t>(t[i])];
    const Vec3 u = soup.points[static_cast<std::size_t>(t[(i + 1) % 3])] - p;
    const Vec3 v = soup.points[static_cast<std::size_t>(t[(i + 2) % 3])] - p;
    const double cross = u.cross(v).norm();
    w[static_cast<std::size_t>(i)] = cross > 0 ? 0.5 * u.dot(v) / cross : 0.0;
  }
  return w;
}

/// Dirichlet energy of a complex linear function on a triangle (both components).
double face_energy(const std::array<double, 3>& w, const CornerValues& c) {
  double e = 0;
  for (int i = 0; i < 3; ++i) e += w[static_cast<std::size_t>(i)] * std::norm(c[(i + 1) % 3] - c[(i + 2) % 3]);
  return e;
}

/// Minimizes sum_f E_f(psi + c_f) (c a closed form's face potentials, one real
/// component) with psi fixed at `fixed`; returns psi per vertex.
Eigen::VectorXd dirichlet_solve(const TriangleSoup& soup, const std::vector<std::array<double, 3>>& weights,
                                const std::vector<std::array<double, 3>>& potentials,
                                const std::map<int, double>& fixed, const char* component) {
  const std::size_t nV = soup.points.size();
  std::vector<int> index(nV, -1);
  int free_count = 0;
  for (std::size_t v = 0; v < nV; ++v)
    if (!fixed.count(static_cast<int>(v))) index[v] = free_count++;
  Eigen::VectorXd psi = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nV));
  for (const auto& [v, value] : fixed) psi[v] = value;
  if (free_count == 0) return psi;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free_count);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    for (int i = 0; i < 3; ++i) {
      const int j = t[(i + 1) % 3], k = t[(i + 2) % 3];
      const int jl = (i + 1) % 3, kl = (i + 2) % 3;
      const double w = weights[f][static_cast<std::size_t>(i)];
      // energy w (psi_j - psi_k + c_j - c_k)^2: gradient rows j and k
      const double dc = potentials[f][static_cast<std::size_t>(jl)] - potentials[f][static_cast<std::size_t>(kl)];
      for (int side = 0; side < 2; ++side) {
        const int a = side ? k : j, b = side ? j : k;
        const double sign = side ? -1.0 : 1.0;
        const int ia = index[static_cast<std::size_t>(a)];
        if (ia < 0) continue;
        triplets.emplace_back(ia, ia, w);
        const int ib = index[static_cast<std::size_t>(b)];
        if (ib >= 0)
          triplets.emplace_back(ia, ib, -w);
        else
          rhs[ia] += w * psi[b];
        rhs[ia] -= w * sign * dc;
      }
    }
  }
  SparseMatrix L(free_count, free_count);
  L.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> solver;
  solver.compute(L);
  if (solver.info() != Eigen::Success)
    throw Error(ErrorCode::solver,
                fmt::format("the {} quantization system could not be factored (degenerate triangles?)",
                            component));
  const Eigen::VectorXd x = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !x.allFinite())
    throw Error(ErrorCode::solver, fmt::format("the {} quantization solve failed", component));
  for (std::size_t v = 0; v < nV; ++v)
    if (index[v] >= 0) psi[static_cast<Eigen::Index>(v)] = x[index[v]];
  return psi;
}

/// The value of a face map at vertex v in the chart of one of its triangles.
Complex value_at(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& map, int v) {
  const int f = adjacency.vertex_faces[static_cast<std::size_t>(v)].front();
  const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
  for (int i = 0; i < 3; ++i)
    if (t[i] == v) return map.corners[static_cast<std::size_t>(f)][i];
  QM_ASSERT(false);
  return {};
}


/// The vertices around a cone that the local model fixes, with the model's and
/// the target's values relative to the cone.
struct ConeDisk {
  Complex a;                    ///< the model's coefficient
  std::size_t star = 0;         ///< vertices[0, star) are the star's
  std::vector<int> vertices;
  std::vector<Complex> model;   ///< a W(v)
  std::vector<Complex> target;  ///< integral of xi from the cone to v
};

/// The disk: the cone's star and every vertex reached from it whose target image
/// lies within `disk_radius` of the cone's (breadth first; `constrained` vertices
/// are crossed but not listed). `fixed_a`: use this coefficient instead of fitting. The model: the disk projected on the tangent plane at
/// the cone, polar coordinates (r, t) with t counter-clockwise from the first star
/// neighbour (for a boundary cone, from the boundary edge leaving it, over the
/// range T of the star), W = r^g e^(i g t) with g = image angle / (2 pi or T), and
/// a fitted to the target in least squares (real on the boundary, which keeps it
/// horizontal). For a zero of order m inside, W = (x + iy)^(m+1): fold-free.
ConeDisk cone_disk(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& xi,
                   const ZeroVertex& cone, const std::vector<char>& constrained, const Complex* fixed_a,
                   double radius = disk_radius) {
  const int c = cone.vertex;
  const VertexRing ring = vertex_ring(soup, adjacency, c);
  std::unordered_map<int, Complex> reach{{c, Complex(0, 0)}};
  std::vector<int> order;
  for (int v : ring.neighbours) {
    reach[v] = edge_value(adjacency, xi, c, v);
    if (!constrained[static_cast<std::size_t>(v)]) order.push_back(v);
  }
  std::vector<int> frontier = ring.neighbours;
  while (!frontier.empty()) {
    std::vector<int> next;
    for (int u : frontier)
      for (int f : adjacency.vertex_faces[static_cast<std::size_t>(u)])
        for (int v : soup.triangles[static_cast<std::size_t>(f)]) {
          if (reach.count(v) || constrained[static_cast<std::size_t>(v)]) continue;
          const Complex at = reach[u] + edge_value(adjacency, xi, u, v);
          if (std::abs(at) > radius) continue;
          reach[v] = at;
          order.push_back(v);
          next.push_back(v);
        }
    frontier.swap(next);
  }
  // tangent frame at the cone: normal from the star, x towards the first neighbour
  const Vec3& p = soup.points[static_cast<std::size_t>(c)];
  Vec3 normal = Vec3::Zero();
  for (int f : adjacency.vertex_faces[static_cast<std::size_t>(c)]) {
    const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
    normal += (soup.points[static_cast<std::size_t>(t[1])] - soup.points[static_cast<std::size_t>(t[0])])
                  .cross(soup.points[static_cast<std::size_t>(t[2])] - soup.points[static_cast<std::size_t>(t[0])]);
  }
  normal.normalize();
  Vec3 x = soup.points[static_cast<std::size_t>(ring.neighbours.front())] - p;
  x = (x - x.dot(normal) * normal).normalized();
  const Vec3 y = normal.cross(x);
  auto polar_of = [&](int v) {
    const Vec3 d = soup.points[static_cast<std::size_t>(v)] - p;
    double t = std::atan2(d.dot(y), d.dot(x));
    if (t < 0) t += 2 * M_PI;
    return std::make_pair(std::hypot(d.dot(x), d.dot(y)), t);
  };
  double range = 2 * M_PI;
  if (cone.on_boundary) range = polar_of(ring.neighbours.back()).second;
  const double g = cone.image_angle() / range;
  ConeDisk disk;
  Complex num = 0;
  double den = 0;
  std::vector<Complex> W;
  // the star itself: intrinsic polar coordinates (3D distances, cumulative 3D
  // angles scaled to the image angle), monotone around the cone, hence fold-free
  std::unordered_map<int, Complex> star_w;
  {
    const std::size_t n = ring.neighbours.size();
    const std::vector<double> angles = ring_angles(soup, ring, c);
    std::vector<double> theta(n, 0.0);
    double total = 0;
    for (std::size_t k = 0; k < angles.size(); ++k) {
      if (k + 1 < n) theta[k + 1] = theta[k] + angles[k];
      total += angles[k];
    }
    const double gs = cone.image_angle() / total;
    for (std::size_t k = 0; k < n; ++k) {
      const double r = (soup.points[static_cast<std::size_t>(ring.neighbours[k])] - p).norm();
      star_w[ring.neighbours[k]] = std::polar(std::pow(r, gs), theta[k] * gs);
    }
  }
  for (int v : order) {
    auto [r, t] = polar_of(v);
    if (cone.on_boundary) t = std::min(t, range);
    const auto in_star = star_w.find(v);
    W.push_back(in_star != star_w.end() ? in_star->second : std::polar(std::pow(r, g), t * g));
    num += std::conj(W.back()) * reach[v];
    den += std::norm(W.back());
  }
  Complex a = den > 0 ? num / den : Complex(1, 0);
  if (cone.on_boundary) a = Complex(a.real(), 0);
  if (fixed_a) a = *fixed_a;
  disk.a = a;
  const std::size_t star = static_cast<std::size_t>(std::count_if(
      order.begin(), order.end(), [&](int v) {
        return std::find(ring.neighbours.begin(), ring.neighbours.end(), v) != ring.neighbours.end();
      }));
  disk.star = star;
  for (std::size_t k = 0; k < order.size(); ++k) {
    // pure model on the star, blending smoothly into the target towards the rim;
    // a corner's whole disk is the target translated (the target's image angle at a
    // corner is already pi and not folded: it needs no bending there)
    const double rho = std::abs(reach[order[k]]) / radius;
    double beta = cone.corner ? 1.0 : k < star ? 0.0 : std::clamp((rho - blend_start) / blend_width, 0.0, 1.0);
    beta = beta * beta * (3 - 2 * beta);
    disk.vertices.push_back(order[k]);
    disk.model.push_back((1 - beta) * a * W[k] + beta * reach[order[k]]);
    disk.target.push_back(reach[order[k]]);
  }
  return disk;
}

}  // namespace

double round_nonzero(double x) {
  const double r = std::round(x);
  if (r == 0 && std::abs(x) > collapse_threshold) return x > 0 ? 1.0 : -1.0;
  return r;
}

std::vector<double> round_levels(const std::vector<double>& levels) {
  const std::size_t n = levels.size();
  if (n == 0) return {};
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return levels[a] < levels[b]; });
  // dynamic programming over a few integer candidates per level (in sorted
  // order): least squared rounding with every level >= the one before, and > when
  // they differ by more than 1/4
  constexpr int span = 3;
  std::vector<std::vector<double>> cost(n, std::vector<double>(2 * span + 1, std::numeric_limits<double>::max()));
  std::vector<std::vector<int>> from(n, std::vector<int>(2 * span + 1, -1));
  auto candidate = [&](std::size_t i, int c) { return std::round(levels[order[i]]) + (c - span); };
  for (int c = 0; c <= 2 * span; ++c) cost[0][static_cast<std::size_t>(c)] = std::pow(candidate(0, c) - levels[order[0]], 2);
  for (std::size_t i = 1; i < n; ++i) {
    const bool apart = levels[order[i]] - levels[order[i - 1]] > collapse_threshold;
    for (int c = 0; c <= 2 * span; ++c)
      for (int p = 0; p <= 2 * span; ++p) {
        const double here = candidate(i, c), there = candidate(i - 1, p);
        if (here < there || (apart && here == there)) continue;
        const double total = cost[i - 1][static_cast<std::size_t>(p)] + std::pow(here - levels[order[i]], 2);
        if (total < cost[i][static_cast<std::size_t>(c)]) {
          cost[i][static_cast<std::size_t>(c)] = total;
          from[i][static_cast<std::size_t>(c)] = p;
        }
      }
  }
  std::vector<double> out(n, 0.0);
  int c = static_cast<int>(std::min_element(cost[n - 1].begin(), cost[n - 1].end()) - cost[n - 1].begin());
  for (std::size_t i = n; i-- > 0;) {
    out[order[i]] = candidate(i, c);
    if (i > 0) c = from[i][static_cast<std::size_t>(c)];
  }
  // an integer shift so that levels[0] keeps its own rounding (boundary 0 at 0)
  const double offset = std::round(levels[0]) - out[0];
  for (double& x : out) x += offset;
  return out;
}

Complex path_integral(const SurfaceAdjacency& adjacency, const FaceMap& form,
                      const std::vector<int>& path, bool closed) {
  Complex sum = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) sum += edge_value(adjacency, form, path[i], path[i + 1]);
  if (closed && path.size() > 1) sum += edge_value(adjacency, form, path.back(), path.front());
  return sum;
}

FaceMap integrate_cut(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& form,
                      int base) {
  const std::size_t nF = soup.triangles.size();
  FaceMap out = form;
  std::vector<char> done(nF, 0);
  auto shift = [&](std::size_t f, Complex by) {
    for (Complex& z : out.corners[f]) z += by;
  };
  const int first = adjacency.vertex_faces[static_cast<std::size_t>(base)].front();
  {
    const Triangle& t = soup.triangles[static_cast<std::size_t>(first)];
    for (int i = 0; i < 3; ++i)
      if (t[i] == base) shift(static_cast<std::size_t>(first), -form.corners[static_cast<std::size_t>(first)][i]);
  }
  std::queue<int> queue;
  auto start = [&](int f) {
    done[static_cast<std::size_t>(f)] = 1;
    queue.push(f);
  };
  start(first);
  for (std::size_t seed = 0;; ++seed) {
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
      for (int i = 0; i < 3; ++i) {
        const int a = t[i], b = t[(i + 1) % 3];
        const EdgeCorner g = adjacency.find(b, a);
        if (g.face < 0 || done[static_cast<std::size_t>(g.face)]) continue;
        // g holds b at corner g.i and a at corner g.j: match the value at a
        shift(static_cast<std::size_t>(g.face),
              out.corners[static_cast<std::size_t>(f)][i] - out.corners[static_cast<std::size_t>(g.face)][g.j]);
        start(g.face);
      }
    }
    while (seed < nF && done[seed]) ++seed;
    if (seed >= nF) break;
    start(static_cast<int>(seed));  // another component (not expected)
  }
  return out;
}

namespace {

/// A loop whose period is rounded, named for the report.
struct NamedPath {
  std::string name;
  const std::vector<int>* path;
};

/// The period correction of step 1-2: xi = T + C, with C = sum_k e_k Re(h_k) +
/// i d_k Im(h_k) giving xi integer periods on the handle and boundary loops.
struct PeriodCorrection {
  FaceMap C;   ///< xi - T
  FaceMap xi;  ///< the target with integer periods
};

/// Least-squares coefficients of the basis that move the periods of `target` on
/// `list` (real or imaginary parts) to their rounding (round_nonzero), appended to
/// `rounded`.
Eigen::VectorXd period_coefficients(const SurfaceAdjacency& adjacency, const FaceMap& target,
                                    const std::vector<FaceMap>& basis, const std::vector<NamedPath>& list,
                                    bool imaginary, std::vector<double>& rounded) {
  const Eigen::Index K = static_cast<Eigen::Index>(basis.size());
  const Eigen::Index n = static_cast<Eigen::Index>(list.size());
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(K);
  if (n == 0) return coefficients;
  Eigen::MatrixXd M(n, K);
  Eigen::VectorXd delta(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& path = *list[static_cast<std::size_t>(j)].path;
    for (Eigen::Index k = 0; k < K; ++k) {
      const Complex p = path_integral(adjacency, basis[static_cast<std::size_t>(k)], path, true);
      M(j, k) = imaginary ? p.imag() : p.real();
    }
    const Complex p = path_integral(adjacency, target, path, true);
    const double value = imaginary ? p.imag() : p.real();
    rounded.push_back(round_nonzero(value));
    delta[j] = rounded.back() - value;
  }
  coefficients = M.completeOrthogonalDecomposition().solve(delta);
  return coefficients;
}

/// Steps 1 and 2: the periods of T and of the basis on the loops of H_1(S), and
/// xi = T + the corrections; the rounded periods as they came out go to q.periods.
PeriodCorrection correct_periods(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const FaceMap& target, const std::vector<FaceMap>& basis,
                                 const NamedLoops& loops, Quantization& q) {
  const std::size_t nF = soup.triangles.size();
  const Eigen::Index K = static_cast<Eigen::Index>(basis.size());
  std::vector<NamedPath> u_loops, v_loops;
  for (std::size_t i = 0; i < loops.handles.size(); ++i) {
    u_loops.push_back({fmt::format("handle_{}", i), &loops.handles[i]});
    v_loops.push_back(u_loops.back());
  }
  for (std::size_t k = 1; k < loops.boundaries.size(); ++k)
    u_loops.push_back({fmt::format("boundary_{}", k), &loops.boundaries[k]});
  std::vector<double> u_rounded, v_rounded;
  const Eigen::VectorXd e = period_coefficients(adjacency, target, basis, u_loops, false, u_rounded);
  const Eigen::VectorXd d = period_coefficients(adjacency, target, basis, v_loops, true, v_rounded);

  PeriodCorrection out;
  FaceMap& C = out.C;
  C.corners.assign(nF, CornerValues{});
  for (Eigen::Index k = 0; k < K; ++k)
    for (std::size_t f = 0; f < nF; ++f)
      for (int i = 0; i < 3; ++i) {
        const Complex b = basis[static_cast<std::size_t>(k)].corners[f][i];
        C.corners[f][i] += Complex(e[k] * b.real(), d[k] * b.imag());
      }
  out.xi = target;
  for (std::size_t f = 0; f < nF; ++f)
    for (int i = 0; i < 3; ++i) out.xi.corners[f][i] += C.corners[f][i];
  // the rounded periods as they came out (exact integers up to round-off)
  for (std::size_t j = 0; j < u_loops.size(); ++j) {
    const Complex before = path_integral(adjacency, target, *u_loops[j].path, true);
    const Complex after = path_integral(adjacency, out.xi, *u_loops[j].path, true);
    q.periods.push_back({u_loops[j].name, before, after});
  }
  return out;
}

/// Step 3's state: the Dirichlet values of psi (U and V) and the cones.
struct DirichletValues {
  std::map<int, double> fixed_u, fixed_v;
  std::vector<int> loop_of;          ///< per vertex: its boundary loop, or -1
  std::vector<char> is_cone;         ///< per vertex
  std::vector<char> constrained;     ///< per vertex: 1 a cone, 2 in a cone's disk
  std::vector<const ZeroVertex*> cones;  ///< the zeros, then the corners kept
  std::unordered_map<int, double> boundary_zero_psi;  ///< U-psi of each boundary zero
};

/// Rule 2: V constant on each boundary loop, the loops' levels (the V-integrals of
/// the bridges) rounded together (round_levels); the bridges' periods go to q.periods.
void fix_boundary_levels(const SurfaceAdjacency& adjacency, const FaceMap& target, const FaceMap& xi,
                         const NamedLoops& loops, DirichletValues& dv, Quantization& q) {
  dv.loop_of = boundary_loop_of_vertex(loops, dv.loop_of.size());
  std::vector<double> level(loops.boundaries.size(), 0.0);
  for (std::size_t k = 1; k < loops.boundaries.size(); ++k)
    level[k] = path_integral(adjacency, xi, loops.bridges[k - 1], false).imag();
  const std::vector<double> rounded = round_levels(level);
  std::vector<double> shift(loops.boundaries.size(), 0.0);
  for (std::size_t k = 1; k < loops.boundaries.size(); ++k) {
    shift[k] = rounded[k] - level[k];
    q.periods.push_back({fmt::format("bridge_{}", k),
                         Complex(0, path_integral(adjacency, target, loops.bridges[k - 1], false).imag()),
                         Complex(0, rounded[k])});
  }
  for (std::size_t v = 0; v < dv.loop_of.size(); ++v)
    if (dv.loop_of[v] >= 0) dv.fixed_v[static_cast<int>(v)] = shift[static_cast<std::size_t>(dv.loop_of[v])];
}

/// The cones: the zeros, then the corners that do not share a lattice point with
/// the cone met before them along their loop. Consecutive zeros along a loop take
/// distinct integers U (the boundary arc between them is monotone in U and would
/// collapse): a zero that would round onto the one before it takes the next integer
/// in the direction of travel.
void choose_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& xi,
                  const FaceMap& Xi, const std::vector<ZeroVertex>& zeros, const NamedLoops& loops,
                  DirichletValues& dv, Quantization& q) {
  std::unordered_map<int, const ZeroVertex*> corner_at;
  for (const ZeroVertex& z : zeros) {
    if (z.corner) {
      corner_at[z.vertex] = &z;
      continue;
    }
    dv.cones.push_back(&z);
    dv.is_cone[static_cast<std::size_t>(z.vertex)] = 1;
  }
  for (const auto& loop : loops.boundaries) {
    double position = value_at(soup, adjacency, Xi, loop.front()).real();
    double last_lattice = std::nan(""), last_position = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int v = loop[i];
      if (i > 0) position += edge_value(adjacency, xi, loop[i - 1], v).real();
      if (dv.is_cone[static_cast<std::size_t>(v)]) {
        double u = std::round(position);
        if (u == last_lattice) u += position >= last_position ? 1 : -1;
        dv.boundary_zero_psi[v] = u - position;
        last_lattice = u;
        last_position = position;
        continue;
      }
      const auto corner = corner_at.find(v);
      if (corner == corner_at.end()) continue;
      if (std::round(position) == last_lattice) {
        ++q.corners_dropped;
        continue;
      }
      dv.cones.push_back(corner->second);
      dv.is_cone[static_cast<std::size_t>(v)] = 1;
      last_lattice = std::round(position);
      last_position = position;
      ++q.corners;
    }
  }
}

/// Rule 3: each cone on its lattice point with the local model on its star, then
/// on the rest of a disk around it; a corner in the star of a cone before it stays
/// free.
void place_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& xi,
                 const FaceMap& Xi, DirichletValues& dv, Quantization& q) {
  auto lattice = [&](int v) {  // psi making v a lattice point (chart independent)
    const Complex x = value_at(soup, adjacency, Xi, v);
    return Complex(std::round(x.real()) - x.real(), std::round(x.imag()) - x.imag());
  };
  std::vector<const ZeroVertex*> placed;
  std::vector<Complex> placed_psi, placed_a;
  auto apply = [&](const ConeDisk& disk, Complex psi_cone, std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const int v = disk.vertices[k];
      if (dv.constrained[static_cast<std::size_t>(v)]) continue;
      const Complex psi = psi_cone + disk.model[k] - disk.target[k];
      dv.fixed_u[v] = psi.real();
      if (dv.loop_of[static_cast<std::size_t>(v)] < 0) dv.fixed_v[v] = psi.imag();
      dv.constrained[static_cast<std::size_t>(v)] = 2;
    }
  };
  for (const ZeroVertex* z : dv.cones) {
    if (z->corner && dv.constrained[static_cast<std::size_t>(z->vertex)]) {
      --q.corners;
      ++q.corners_dropped;
      continue;
    }
    Complex lattice_psi = lattice(z->vertex);
    if (const auto it = dv.boundary_zero_psi.find(z->vertex); it != dv.boundary_zero_psi.end())
      lattice_psi.real(it->second);
    dv.fixed_u[z->vertex] = lattice_psi.real();
    if (!z->on_boundary) dv.fixed_v[z->vertex] = lattice_psi.imag();
    dv.constrained[static_cast<std::size_t>(z->vertex)] = 1;
    if (!z->corner) ++q.lattice_zeros;
    const Complex psi_cone(lattice_psi.real(), dv.fixed_v[z->vertex]);
    const ConeDisk disk = cone_disk(soup, adjacency, xi, *z, dv.constrained, nullptr);
    apply(disk, psi_cone, 0, disk.star);
    placed.push_back(z);
    placed_psi.push_back(psi_cone);
    placed_a.push_back(disk.a);
  }
  for (std::size_t c = 0; c < placed.size(); ++c) {
    // the disks of two cones closer than two radii would overlap: each takes its half
    // (a vertex of two disks would follow the cone met first, and the other cone's
    // star would sit in a translated neighbourhood: folds)
    double radius = disk_radius;
    const auto cone_at = [&](int v) { return dv.is_cone[static_cast<std::size_t>(v)] != 0; };
    for (const auto& [v, d] : image_ball(soup, adjacency, xi, placed[c]->vertex, 2 * disk_radius, cone_at))
      if (v != placed[c]->vertex && cone_at(v)) radius = std::min(radius, 0.5 * d);
    const ConeDisk disk = cone_disk(soup, adjacency, xi, *placed[c], dv.constrained, &placed_a[c], radius);
    apply(disk, placed_psi[c], 0, disk.vertices.size());
  }
}

/// Step 4: psi by two sparse solves, Phi = Xi + psi, and the distortion and flips
/// of the result.
void solve_psi(const TriangleSoup& soup, const FaceMap& target, const FaceMap& C, const FaceMap& Xi,
               const DirichletValues& dv, Quantization& q) {
  const std::size_t nF = soup.triangles.size();
  std::vector<std::array<double, 3>> weights(nF), cu(nF), cv(nF);
  for (std::size_t f = 0; f < nF; ++f) {
    weights[f] = corner_weights(soup, soup.triangles[f]);
    for (int i = 0; i < 3; ++i) {
      cu[f][static_cast<std::size_t>(i)] = C.corners[f][i].real();
      cv[f][static_cast<std::size_t>(i)] = C.corners[f][i].imag();
    }
  }
  const Eigen::VectorXd psi_u = dirichlet_solve(soup, weights, cu, dv.fixed_u, "U");
  const Eigen::VectorXd psi_v = dirichlet_solve(soup, weights, cv, dv.fixed_v, "V");

  q.param = Xi;
  double change = 0, reference = 0;
  for (std::size_t f = 0; f < nF; ++f) {
    const Triangle& t = soup.triangles[f];
    CornerValues delta{};
    for (int i = 0; i < 3; ++i) {
      const Complex psi(psi_u[t[i]], psi_v[t[i]]);
      q.param.corners[f][i] += psi;
      delta[static_cast<std::size_t>(i)] = q.param.corners[f][i] - target.corners[f][i];
    }
    change += face_energy(weights[f], delta);
    reference += face_energy(weights[f], target.corners[f]);
    if (image_area2(q.param.corners[f]) <= 0) ++q.flipped;
  }
  q.distortion = reference > 0 ? change / reference : 0.0;
}

}  // namespace

Quantization quantize(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                      const FaceMap& target, const std::vector<FaceMap>& basis,
                      const std::vector<ZeroVertex>& zeros, const NamedLoops& loops) {
  QM_ASSERT(!loops.boundaries.empty() && !basis.empty());
  const std::size_t nV = soup.points.size();
  Quantization q;
  // 1-2. periods rounded: xi = T + C
  const PeriodCorrection corrected = correct_periods(soup, adjacency, target, basis, loops, q);
  const int base = loops.boundaries[0].front();
  const FaceMap Xi = integrate_cut(soup, adjacency, corrected.xi, base);
  // 3. Dirichlet values of psi: boundary levels, then the cones
  DirichletValues dv;
  dv.loop_of.assign(nV, -1);
  dv.is_cone.assign(nV, 0);
  dv.constrained.assign(nV, 0);
  fix_boundary_levels(adjacency, target, corrected.xi, loops, dv, q);
  choose_cones(soup, adjacency, corrected.xi, Xi, zeros, loops, dv, q);
  place_cones(soup, adjacency, corrected.xi, Xi, dv, q);
  if (dv.fixed_u.empty()) dv.fixed_u[base] = 0.0;
  q.fixed_vertices = dv.fixed_u.size() + dv.fixed_v.size();
  // 4. two sparse solves
  solve_psi(soup, target, corrected.C, Xi, dv, q);
  return q;
}

}  // namespace qm
