#include "libquadmesh/quality/quad_quality.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/internal/union_find.h"
#include "libquadmesh/quality/corner_quads.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_distance.h"
#include "libquadmesh/quality/size_band.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace qm {

namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// What a quad's corners deviate from, and what a boundary point's faces should
/// span its corner angle sum in.
constexpr double kRightAngleDeg = 90.0;

double angle_between_deg(const Vec3& a, const Vec3& b) {
  return angle_between(a, b) * kDegrees;
}

/// Value at fraction p of the sorted values, interpolated linearly between order
/// statistics (position p (n - 1)); NaN for no values.
double percentile(std::vector<double> values, double p) {
  if (values.empty()) return kNaN;
  std::sort(values.begin(), values.end());
  const double position = p * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double t = position - static_cast<double>(below);
  return (1 - t) * values[below] + t * values[above];
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return kNaN;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double max_of(const std::vector<double>& values) {
  return values.empty() ? kNaN : *std::max_element(values.begin(), values.end());
}

double min_of(const std::vector<double>& values) {
  return values.empty() ? kNaN : *std::min_element(values.begin(), values.end());
}

/// Vector area of a polygon: half the sum of p_i x p_{i+1} (Newell); for a quad it
/// equals (p2 - p0) x (p3 - p1) / 2.
Vec3 vector_area(const PolygonMesh& mesh, const std::vector<int>& face) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < face.size(); ++i)
    sum += mesh.points[static_cast<std::size_t>(face[i])].cross(
        mesh.points[static_cast<std::size_t>(face[(i + 1) % face.size()])]);
  return 0.5 * sum;
}

/// One distinct (undirected) edge a < b and the face corners at its ends, per use.
struct EdgeRecord {
  int a = -1, b = -1;
  int uses = 0;
  int uses_a_to_b = 0;         ///< uses in the direction a -> b
  std::vector<int> corners_a;  ///< per use: the global corner id of the face at a
  std::vector<int> corners_b;  ///< per use: the global corner id of the face at b
};

struct EdgeTable {
  std::vector<EdgeRecord> edges;
  std::vector<std::vector<int>> edges_of_vertex;
};

EdgeTable build_edges(const PolygonMesh& mesh, const std::vector<int>& first_corner) {
  EdgeTable table;
  table.edges_of_vertex.resize(mesh.points.size());
  std::unordered_map<std::uint64_t, int> index;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    const int n = static_cast<int>(face.size());
    for (int c = 0; c < n; ++c) {
      const int from = face[static_cast<std::size_t>(c)];
      const int to = face[static_cast<std::size_t>((c + 1) % n)];
      if (from == to) continue;  // a repeated corner: no edge
      const int a = std::min(from, to), b = std::max(from, to);
      const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) |
                                static_cast<std::uint64_t>(static_cast<std::uint32_t>(b));
      auto [it, inserted] = index.emplace(key, static_cast<int>(table.edges.size()));
      if (inserted) {
        EdgeRecord e;
        e.a = a;
        e.b = b;
        table.edges.push_back(e);
        table.edges_of_vertex[static_cast<std::size_t>(a)].push_back(it->second);
        table.edges_of_vertex[static_cast<std::size_t>(b)].push_back(it->second);
      }
      EdgeRecord& e = table.edges[static_cast<std::size_t>(it->second)];
      ++e.uses;
      const int corner_from = first_corner[f] + c;
      const int corner_to = first_corner[f] + (c + 1) % n;
      if (from == a) {
        ++e.uses_a_to_b;
        e.corners_a.push_back(corner_from);
        e.corners_b.push_back(corner_to);
      } else {
        e.corners_a.push_back(corner_to);
        e.corners_b.push_back(corner_from);
      }
    }
  }
  return table;
}

/// Closed cycles of boundary edges. At each end a boundary edge belongs to one fan
/// (a root of `fans`); a walk enters a point through one boundary edge and leaves
/// through the other boundary edge of the same fan, so loops touching at a pinched
/// point are told apart. Walks that reach a fan without exactly two boundary edges
/// are not counted.
int count_boundary_loops(const EdgeTable& table, UnionFind& fans) {
  std::unordered_map<int, std::vector<int>> boundary_edges_of_fan;
  std::vector<int> boundary;
  for (std::size_t e = 0; e < table.edges.size(); ++e) {
    const EdgeRecord& r = table.edges[e];
    if (r.uses != 1) continue;
    boundary.push_back(static_cast<int>(e));
    boundary_edges_of_fan[fans.find(r.corners_a[0])].push_back(static_cast<int>(e));
    boundary_edges_of_fan[fans.find(r.corners_b[0])].push_back(static_cast<int>(e));
  }
  std::vector<char> visited(table.edges.size(), 0);
  int loops = 0;
  for (int start : boundary) {
    if (visited[static_cast<std::size_t>(start)]) continue;
    int edge = start;
    int fan = fans.find(table.edges[static_cast<std::size_t>(start)].corners_b[0]);
    bool closed = false;
    while (true) {
      visited[static_cast<std::size_t>(edge)] = 1;
      const std::vector<int>& at = boundary_edges_of_fan[fan];
      if (at.size() != 2) break;
      const int next = at[0] == edge ? at[1] : at[0];
      if (next == start) {
        closed = true;
        break;
      }
      if (visited[static_cast<std::size_t>(next)]) break;
      const EdgeRecord& r = table.edges[static_cast<std::size_t>(next)];
      // leave `next` through its end that is not in the fan we came through
      const int fan_a = fans.find(r.corners_a[0]);
      fan = fan_a == fan ? fans.find(r.corners_b[0]) : fan_a;
      edge = next;
    }
    if (closed) ++loops;
  }
  return loops;
}

}  // namespace

std::vector<Vec3> vertex_normals(const PolygonMesh& mesh) {
  std::vector<Vec3> normals(mesh.points.size(), Vec3::Zero());
  for (const std::vector<int>& face : mesh.faces) {
    const Vec3 area = vector_area(mesh, face);
    for (int v : face)
      normals[static_cast<std::size_t>(v)] += area;
  }
  for (Vec3& n : normals) {
    const double length = n.norm();
    n = length > 0 ? Vec3(n / length) : Vec3::Zero();
  }
  return normals;
}

double corner_scaled_jacobian(const Vec3& prev, const Vec3& p, const Vec3& next, const Vec3& n) {
  const Vec3 e1 = next - p, e2 = prev - p;
  const double lengths = e1.norm() * e2.norm();
  if (lengths == 0) return 0;
  return e1.cross(e2).dot(n) / lengths;
}

double corner_angle_deg(const Vec3& prev, const Vec3& p, const Vec3& next) {
  return angle_between_deg(next - p, prev - p);
}

double sound_scaled_jacobian(const QuadPoints& corners, const std::array<Vec3, 4>& normals) {
  double worst = quad_scaled_jacobian(corners);
  for (std::size_t k = 0; k < 4; ++k)
    worst = std::min(worst, corner_scaled_jacobian(corners[(k + 3) % 4], corners[k], corners[(k + 1) % 4], normals[k]));
  return worst;
}

namespace {

/// The unit vertex normals at the corners of a quad, the quad's own (diagonal)
/// normal standing in at a point without one.
std::array<Vec3, 4> corner_normals(const QuadPoints& c, const std::array<int, 4>& ids,
                                   const std::vector<Vec3>& normals) {
  const Vec3 own = (c[2] - c[0]).cross(c[3] - c[1]);
  const Vec3 own_normal = own.norm() > 0 ? Vec3(own.normalized()) : Vec3::Zero();
  std::array<Vec3, 4> n;
  for (std::size_t k = 0; k < 4; ++k) {
    const Vec3& vn = normals[static_cast<std::size_t>(ids[k])];
    n[k] = vn.squaredNorm() > 0 ? vn : own_normal;
  }
  return n;
}

QuadPoints quad_points(const PolygonMesh& mesh, const std::vector<int>& face) {
  QuadPoints c;
  for (std::size_t k = 0; k < 4; ++k) c[k] = mesh.points[static_cast<std::size_t>(face[k])];
  return c;
}

std::array<int, 4> quad_ids(const std::vector<int>& face) { return {face[0], face[1], face[2], face[3]}; }

}  // namespace

std::vector<double> sound_scaled_jacobians(const PolygonMesh& mesh) {
  const std::vector<Vec3> normals = vertex_normals(mesh);
  std::vector<double> out;
  for (const std::vector<int>& face : mesh.faces) {
    if (face.size() != 4) continue;
    const QuadPoints c = quad_points(mesh, face);
    out.push_back(sound_scaled_jacobian(c, corner_normals(c, quad_ids(face), normals)));
  }
  return out;
}

QuadShapeSamples quad_shape_samples(const PolygonMesh& mesh) {
  QuadShapeSamples s;
  const std::vector<Vec3> normals = vertex_normals(mesh);
  for (const std::vector<int>& face : mesh.faces) {
    if (face.size() != 4) continue;
    const QuadPoints c = quad_points(mesh, face);
    const std::array<Vec3, 4> n = corner_normals(c, quad_ids(face), normals);
    s.verdict.push_back(quad_verdict(c));
    // sound: as sound_scaled_jacobian computes it (Verdict's, then each corner's cap)
    double consistency = std::numeric_limits<double>::infinity(), sound = s.verdict.back().scaled_jacobian;
    for (std::size_t k = 0; k < 4; ++k) {
      const Vec3& prev = c[(k + 3) % 4];
      const Vec3& next = c[(k + 1) % 4];
      const double corner = corner_scaled_jacobian(prev, c[k], next, n[k]);
      consistency = std::min(consistency, corner);
      sound = std::min(sound, corner);
      s.angle_deviation_deg.push_back(std::abs(corner_angle_deg(prev, c[k], next) - kRightAngleDeg));
    }
    s.scaled_jacobian.push_back(s.verdict.back().scaled_jacobian);
    s.normal_consistency.push_back(consistency);
    s.sound_scaled_jacobian.push_back(sound);
  }
  return s;
}

namespace {

/// Face counts by corner count; returns the first global corner id of each face
/// (and the corner count after the last).
std::vector<int> count_faces(const PolygonMesh& mesh, QuadQuality& q) {
  const std::size_t point_count = mesh.points.size();
  std::vector<int> first_corner(mesh.faces.size() + 1, 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    QM_ASSERT_MSG(face.size() >= 3, "a face has fewer than 3 corners");
    for (int v : face)
      QM_ASSERT_MSG(v >= 0 && static_cast<std::size_t>(v) < point_count,
                    "a face refers to a point that does not exist");
    first_corner[f + 1] = first_corner[f] + static_cast<int>(face.size());
    if (face.size() == 3)
      ++q.triangles;
    else if (face.size() == 4)
      ++q.quads;
    else
      ++q.other_faces;
  }
  return first_corner;
}

/// Per quad: Verdict figures, normal consistency, sound scaled Jacobian, corner angles.
void measure_quad_shapes(const PolygonMesh& mesh, QuadQuality& q) {
  const QuadShapeSamples samples = quad_shape_samples(mesh);
  const auto figure = [&](double QuadVerdict::*field) {
    std::vector<double> values;
    values.reserve(samples.verdict.size());
    for (const QuadVerdict& v : samples.verdict) values.push_back(v.*field);
    return values;
  };
  const std::vector<double>& jacobians = samples.scaled_jacobian;
  const std::vector<double>& angle_devs = samples.angle_deviation_deg;
  for (double jacobian : jacobians)
    if (jacobian <= 0) ++q.inverted;
  for (double consistency : samples.normal_consistency)
    if (consistency <= 0) ++q.flipped;
  q.min_scaled_jacobian = min_of(jacobians);
  q.mean_scaled_jacobian = mean(jacobians);
  q.p01_scaled_jacobian = percentile(jacobians, 0.01);
  q.min_normal_consistency = min_of(samples.normal_consistency);
  q.min_sound_scaled_jacobian = min_of(samples.sound_scaled_jacobian);
  q.min_angle = min_of(figure(&QuadVerdict::minimum_angle));
  q.max_angle = max_of(figure(&QuadVerdict::maximum_angle));
  const std::vector<double> warpages = figure(&QuadVerdict::warpage);
  q.min_warpage = min_of(warpages);
  q.mean_warpage = mean(warpages);
  const auto mean_and_max = [&](double QuadVerdict::*field, double& mean_out, double& max_out) {
    const std::vector<double> values = figure(field);
    mean_out = mean(values);
    max_out = max_of(values);
  };
  mean_and_max(&QuadVerdict::aspect_ratio, q.aspect_ratio_mean, q.aspect_ratio_max);
  mean_and_max(&QuadVerdict::skew, q.skew_mean, q.skew_max);
  mean_and_max(&QuadVerdict::taper, q.taper_mean, q.taper_max);
  q.angle_dev_mean = mean(angle_devs);
  double squares = 0;
  for (double d : angle_devs)
    squares += d * d;
  q.angle_dev_rms =
      angle_devs.empty() ? kNaN : std::sqrt(squares / static_cast<double>(angle_devs.size()));
  q.angle_dev_p99 = percentile(angle_devs, 0.99);
  q.angle_dev_max = max_of(angle_devs);
}

/// Per triangle: Verdict figures.
void measure_triangle_shapes(const PolygonMesh& mesh, QuadQuality& q) {
  const auto point = [&](int v) -> const Vec3& { return mesh.points[static_cast<std::size_t>(v)]; };
  std::vector<TriangleVerdict> triangle_figures;
  for (const std::vector<int>& face : mesh.faces)
    if (face.size() == 3) triangle_figures.push_back(triangle_verdict({point(face[0]), point(face[1]), point(face[2])}));
  const auto triangle_figure = [&](double TriangleVerdict::*field) {
    std::vector<double> values;
    for (const TriangleVerdict& v : triangle_figures) values.push_back(v.*field);
    return values;
  };
  q.triangle_min_scaled_jacobian = min_of(triangle_figure(&TriangleVerdict::scaled_jacobian));
  q.triangle_min_angle = min_of(triangle_figure(&TriangleVerdict::minimum_angle));
  q.triangle_max_angle = max_of(triangle_figure(&TriangleVerdict::maximum_angle));
  q.triangle_aspect_ratio_max = max_of(triangle_figure(&TriangleVerdict::aspect_ratio));
}

/// The edges and, per point, whether it is on the boundary and its face corners.
struct Connectivity {
  EdgeTable table;
  std::vector<char> on_boundary;
  std::vector<std::vector<int>> corners_of_point;
};

/// Edges, fans and topology: manifoldness, orientation, vertex count, Euler
/// characteristic, boundary loops.
Connectivity measure_topology(const PolygonMesh& mesh, const std::vector<int>& first_corner, QuadQuality& q) {
  const std::size_t point_count = mesh.points.size();
  Connectivity c;
  c.table = build_edges(mesh, first_corner);
  const EdgeTable& table = c.table;
  UnionFind fans(static_cast<std::size_t>(first_corner.back()));
  c.on_boundary.assign(point_count, 0);
  for (const EdgeRecord& e : table.edges) {
    if (e.uses > 2) q.manifold = false;
    if (e.uses == 1)
      c.on_boundary[static_cast<std::size_t>(e.a)] = c.on_boundary[static_cast<std::size_t>(e.b)] = 1;
    if (e.uses == 2) {
      if (e.uses_a_to_b != 1) q.consistently_oriented = false;
      fans.unite(e.corners_a[0], e.corners_a[1]);
      fans.unite(e.corners_b[0], e.corners_b[1]);
    }
  }
  // corners per point; the fans of a point are the distinct roots of its corners
  c.corners_of_point.resize(point_count);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (std::size_t k = 0; k < mesh.faces[f].size(); ++k)
      c.corners_of_point[static_cast<std::size_t>(mesh.faces[f][k])].push_back(first_corner[f] +
                                                                               static_cast<int>(k));
  for (const std::vector<int>& corners : c.corners_of_point) {
    if (corners.empty()) continue;
    ++q.vertices;
    const int root = fans.find(corners[0]);
    for (int corner : corners)
      if (fans.find(corner) != root) q.manifold = false;
  }
  q.euler_characteristic = static_cast<int>(q.vertices) - static_cast<int>(table.edges.size()) +
                           static_cast<int>(mesh.faces.size());
  q.boundary_loops = count_boundary_loops(table, fans);
  return c;
}

/// Valences against the regular grid.
void measure_valences(const PolygonMesh& mesh, const Connectivity& c, QuadQuality& q) {
  const auto point = [&](int v) -> const Vec3& { return mesh.points[static_cast<std::size_t>(v)]; };
  const std::size_t point_count = mesh.points.size();
  std::vector<double> angle_sum(point_count, 0.0);
  for (const std::vector<int>& face : mesh.faces) {
    const std::size_t n = face.size();
    for (std::size_t k = 0; k < n; ++k)
      angle_sum[static_cast<std::size_t>(face[k])] +=
          corner_angle_deg(point(face[(k + n - 1) % n]), point(face[k]), point(face[(k + 1) % n]));
  }
  for (std::size_t v = 0; v < point_count; ++v) {
    if (c.corners_of_point[v].empty()) continue;
    if (c.on_boundary[v]) {
      const int faces = static_cast<int>(c.corners_of_point[v].size());
      ++q.valence_boundary[faces];
      const int ideal = std::max(1, static_cast<int>(std::lround(angle_sum[v] / kRightAngleDeg)));
      if (faces != ideal) ++q.irregular_boundary;
    } else {
      const int edges = static_cast<int>(c.table.edges_of_vertex[v].size());
      ++q.valence_interior[edges];
      if (edges != 4) ++q.irregular_interior;
    }
  }
}

/// Edge lengths, and the alignment of the interior edges at the boundary against
/// the tangent prev -> next.
void measure_edges(const PolygonMesh& mesh, const Connectivity& c, QuadQuality& q) {
  const auto point = [&](int v) -> const Vec3& { return mesh.points[static_cast<std::size_t>(v)]; };
  const EdgeTable& table = c.table;
  std::vector<double> lengths;
  lengths.reserve(table.edges.size());
  for (const EdgeRecord& e : table.edges)
    lengths.push_back((point(e.b) - point(e.a)).norm());
  q.edge_length_min = min_of(lengths);
  q.edge_length_mean = mean(lengths);
  q.edge_length_max = max_of(lengths);

  std::vector<double> alignment;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (!c.on_boundary[v]) continue;
    std::vector<int> neighbours;
    for (int e : table.edges_of_vertex[v]) {
      const EdgeRecord& r = table.edges[static_cast<std::size_t>(e)];
      if (r.uses == 1) neighbours.push_back(r.a == static_cast<int>(v) ? r.b : r.a);
    }
    if (neighbours.size() != 2) continue;  // a pinched point: no single tangent
    const Vec3 tangent = point(neighbours[1]) - point(neighbours[0]);
    if (tangent.squaredNorm() == 0) continue;
    for (int e : table.edges_of_vertex[v]) {
      const EdgeRecord& r = table.edges[static_cast<std::size_t>(e)];
      if (r.uses != 2) continue;
      const Vec3 edge = point(r.a == static_cast<int>(v) ? r.b : r.a) - mesh.points[v];
      alignment.push_back(std::abs(angle_between_deg(edge, tangent) - kRightAngleDeg));
    }
  }
  q.boundary_alignment_mean = mean(alignment);
  q.boundary_alignment_max = max_of(alignment);
}

/// Two-sided Hausdorff distance to the reference (NaN without one).
void measure_hausdorff(const PolygonMesh& mesh, const TriangleSoup* reference, QuadQuality& q) {
  q.hausdorff_rel = q.hausdorff_forward_rel = q.hausdorff_backward_rel = kNaN;
  if (reference == nullptr) return;
  const QuadDistance d = quad_distance(mesh, *reference);
  q.hausdorff_at = d.farthest;
  const double diagonal = bounding_box_diagonal(reference->points, reference->triangles);
  if (diagonal > 0) {
    q.hausdorff_forward_rel = d.distance.forward / diagonal;
    q.hausdorff_backward_rel = d.distance.backward / diagonal;
    q.hausdorff_rel = d.distance.value() / diagonal;
  }
}

/// Quad sizes against the target (NaN without one).
void measure_size_band(const PolygonMesh& mesh, double target_size, QuadQuality& q) {
  q.size_band_share = q.size_ratio_max = q.size_ratio_min = kNaN;
  if (!(target_size > 0)) return;
  const SizeBand band = quad_size_band(mesh, target_size);
  q.size_band_share = band.share_in_band;
  q.size_ratio_max = band.max_ratio;
  q.size_ratio_min = band.min_ratio;
}

/// The reference's corners, at the target's scale when there is one, and the quads at each.
void measure_corners(const PolygonMesh& mesh, const TriangleSoup* reference, double target_size, QuadQuality& q) {
  if (!reference) return;
  const CornerQuads c = corner_quads(mesh, *reference, target_size);
  q.corners_convex = c.convex;
  q.corners_convex_wrong = c.convex_wrong;
  q.corners_concave = c.concave;
  q.corners_concave_wrong = c.concave_wrong;
  q.corners_other = c.other;
  q.corners_other_wrong = c.other_wrong;
}

}  // namespace

QuadQuality quad_quality(const PolygonMesh& mesh, const TriangleSoup* reference, double target_size) {
  QuadQuality q;
  const std::vector<int> first_corner = count_faces(mesh, q);
  measure_quad_shapes(mesh, q);
  measure_triangle_shapes(mesh, q);
  const Connectivity connectivity = measure_topology(mesh, first_corner, q);
  measure_valences(mesh, connectivity, q);
  measure_edges(mesh, connectivity, q);
  measure_hausdorff(mesh, reference, q);
  measure_size_band(mesh, target_size, q);
  measure_corners(mesh, reference, target_size, q);
  return q;
}

}  // namespace qm
