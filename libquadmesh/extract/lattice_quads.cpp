#include "libquadmesh/extract/lattice_quads.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/internal/union_find.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <unordered_map>

namespace qm {

namespace {

using I64 = std::int64_t;
using I128 = __int128;

struct P2 {
  I64 x = 0, y = 0;
};
P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
bool operator==(P2 a, P2 b) { return a.x == b.x && a.y == b.y; }

/// Sign of (b - a) x (c - a), exactly.
int orient(P2 a, P2 b, P2 c) {
  const I128 d = I128(b.x - a.x) * I128(c.y - a.y) - I128(b.y - a.y) * I128(c.x - a.x);
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

I64 floor_div(I64 a, I64 b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
I64 ceil_div(I64 a, I64 b) { return -floor_div(-a, b); }

/// Cells k with k S < max and (k + 1) S > min (open ranges overlap).
std::pair<I64, I64> cell_range(I64 lo, I64 hi) {
  return {floor_div(lo, lattice_scale), ceil_div(hi, lattice_scale) - 1};
}

/// The cells [k0, k1] x [l0, l1] that a fixed-point triangle's bounding box meets.
std::array<I64, 4> cell_box(const std::array<P2, 3>& t) {
  const auto [k0, k1] = cell_range(std::min({t[0].x, t[1].x, t[2].x}), std::max({t[0].x, t[1].x, t[2].x}));
  const auto [l0, l1] = cell_range(std::min({t[0].y, t[1].y, t[2].y}), std::max({t[0].y, t[1].y, t[2].y}));
  return {k0, k1, l0, l1};
}

struct CellKey {
  int face;
  I64 k, l;
  bool operator==(const CellKey& o) const { return face == o.face && k == o.k && l == o.l; }
};
struct CellKeyHash {
  std::size_t operator()(const CellKey& c) const {
    return std::hash<I64>()((I64(c.face) * 1000003 + c.k) * 1000033 + c.l);
  }
};

std::array<P2, 4> square(I64 k, I64 l) {
  const I64 S = lattice_scale;
  return {P2{k * S, l * S}, P2{(k + 1) * S, l * S}, P2{(k + 1) * S, (l + 1) * S}, P2{k * S, (l + 1) * S}};
}

/// Open triangle (CCW) meets open square: no edge line has the whole square on its right.
bool triangle_meets_cell(const std::array<P2, 3>& t, I64 k, I64 l) {
  const auto sq = square(k, l);
  for (int i = 0; i < 3; ++i) {
    bool all_right = true;
    for (const P2& c : sq)
      if (orient(t[i], t[(i + 1) % 3], c) > 0) {
        all_right = false;
        break;
      }
    if (all_right) return false;
  }
  return true;
}

/// The open segment ab crosses the open square (bounding ranges overlap by construction).
bool segment_meets_cell(P2 a, P2 b, I64 k, I64 l) {
  bool left = false, right = false;
  for (const P2& c : square(k, l)) {
    const int o = orient(a, b, c);
    left |= o > 0;
    right |= o < 0;
  }
  return left && right;
}

/// Area (in lattice units^2) of the triangle clipped to the cell.
double clipped_area(const std::array<P2, 3>& t, I64 k, I64 l) {
  const double S = static_cast<double>(lattice_scale);
  std::vector<std::array<double, 2>> poly;
  for (const P2& p : t) poly.push_back({p.x / S - static_cast<double>(k), p.y / S - static_cast<double>(l)});
  for (int side = 0; side < 4; ++side) {
    auto inside = [&](const std::array<double, 2>& p) {
      switch (side) {
        case 0: return p[0] >= 0.0;
        case 1: return p[0] <= 1.0;
        case 2: return p[1] >= 0.0;
        default: return p[1] <= 1.0;
      }
    };
    auto cut = [&](const std::array<double, 2>& p, const std::array<double, 2>& q) {
      const int axis = side < 2 ? 0 : 1;
      const double bound = (side % 2 == 0) ? 0.0 : 1.0;
      const double s = (bound - p[axis]) / (q[axis] - p[axis]);
      return std::array<double, 2>{p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])};
    };
    std::vector<std::array<double, 2>> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const auto& p = poly[i];
      const auto& q = poly[(i + 1) % poly.size()];
      if (inside(p)) {
        out.push_back(p);
        if (!inside(q)) out.push_back(cut(p, q));
      } else if (inside(q)) {
        out.push_back(cut(p, q));
      }
    }
    poly.swap(out);
    if (poly.empty()) return 0.0;
  }
  double area = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % poly.size()];
    area += p[0] * q[1] - p[1] * q[0];
  }
  return 0.5 * area;
}

struct PointKey {
  int kind, a, b;
  I64 x, y;
  bool operator<(const PointKey& o) const {
    return std::tie(kind, a, b, x, y) < std::tie(o.kind, o.a, o.b, o.x, o.y);
  }
};

/// Charts of two triangles at a vertex whose difference is farther than this
/// (lattice units, per coordinate) from an integer count as a seam mismatch.
constexpr double seam_tolerance = 1e-4;
/// A cell is complete when its pieces' image areas add up to 1 within this
/// (lattice units^2); the areas are clipped in floating point.
constexpr double complete_cell_tolerance = 1e-6;

using Charts = std::vector<std::array<P2, 3>>;

/// The fixed-point image of every triangle corner: the first chart met at each
/// vertex is its reference, the others are that plus an integer translation (so a
/// lattice point on a seam is the same in every chart). Counts seam mismatches.
Charts fixed_point_charts(const TriangleSoup& soup, const FaceMap& param, ExtractionReport& report) {
  const std::size_t nF = soup.triangles.size(), nV = soup.points.size();
  const double S = static_cast<double>(lattice_scale);
  Charts q(nF);
  std::vector<P2> reference(nV);
  std::vector<Complex> reference_value(nV);
  std::vector<char> has_reference(nV, 0);
  for (std::size_t f = 0; f < nF; ++f)
    for (int i = 0; i < 3; ++i) {
      const auto v = static_cast<std::size_t>(soup.triangles[f][i]);
      const Complex z = param.corners[f][i];
      if (!has_reference[v]) {
        has_reference[v] = 1;
        reference_value[v] = z;
        reference[v] = {std::llround(z.real() * S), std::llround(z.imag() * S)};
      }
      const Complex diff = z - reference_value[v];
      const double dx = std::round(diff.real()), dy = std::round(diff.imag());
      if (std::abs(diff.real() - dx) > seam_tolerance || std::abs(diff.imag() - dy) > seam_tolerance)
        ++report.seam_mismatches;
      q[f][static_cast<std::size_t>(i)] =
          reference[v] + P2{static_cast<I64>(dx) * lattice_scale, static_cast<I64>(dy) * lattice_scale};
    }
  return q;
}

/// The triangles used: positive and not absurdly large (a map blown up by a failed
/// repair would otherwise have its lattice enumerated cell by cell). Counts the others.
std::vector<char> usable_triangles(const Charts& q, ExtractionReport& report) {
  auto cells_spanned = [&](const std::array<P2, 3>& t) {
    const auto [k0, k1, l0, l1] = cell_box(t);
    return static_cast<double>(k1 - k0 + 1) * static_cast<double>(l1 - l0 + 1);
  };
  std::vector<char> good(q.size(), 0);
  for (std::size_t f = 0; f < q.size(); ++f) {
    good[f] = orient(q[f][0], q[f][1], q[f][2]) > 0 && cells_spanned(q[f]) <= max_cells_per_triangle;
    if (!good[f] && report.bad_triangles++ == 0) report.first_problem_triangle = static_cast<int>(f);
  }
  return good;
}

/// The pieces: per usable triangle, the cells its open image meets, with the area
/// of the image clipped to the cell.
struct Pieces {
  std::vector<CellKey> keys;
  std::vector<double> area;
  std::unordered_map<CellKey, int, CellKeyHash> index;  ///< of each key in `keys`
};

Pieces cell_pieces(const Charts& q, const std::vector<char>& good) {
  Pieces pieces;
  for (std::size_t f = 0; f < q.size(); ++f) {
    if (!good[f]) continue;
    const auto& t = q[f];
    const auto [k0, k1, l0, l1] = cell_box(t);
    for (I64 k = k0; k <= k1; ++k)
      for (I64 l = l0; l <= l1; ++l)
        if (triangle_meets_cell(t, k, l)) {
          const CellKey key{static_cast<int>(f), k, l};
          pieces.index.emplace(key, static_cast<int>(pieces.keys.size()));
          pieces.keys.push_back(key);
          pieces.area.push_back(clipped_area(t, k, l));
        }
  }
  return pieces;
}

/// The cells: the pieces of two usable triangles sharing an edge are one cell
/// where the open edge crosses the open cell (in the charts' translation). Counts
/// the edges whose two charts differ by more than a lattice translation.
/// Returns the cells as lists of pieces (ascending), ordered by their first piece.
std::vector<std::vector<int>> join_pieces(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                          const Charts& q, const std::vector<char>& good, const Pieces& pieces,
                                          ExtractionReport& report) {
  UnionFind cells(pieces.keys.size());
  for (std::size_t f = 0; f < q.size(); ++f) {
    if (!good[f]) continue;
    for (int i = 0; i < 3; ++i) {
      const int a = soup.triangles[f][i], b = soup.triangles[f][(i + 1) % 3];
      const EdgeCorner g = adjacency.find(b, a);
      if (g.face < 0 || static_cast<std::size_t>(g.face) < f || !good[static_cast<std::size_t>(g.face)]) continue;
      const P2 A = q[f][static_cast<std::size_t>(i)], B = q[f][static_cast<std::size_t>((i + 1) % 3)];
      const P2 tau = q[static_cast<std::size_t>(g.face)][static_cast<std::size_t>(g.j)] - A;
      if (!(q[static_cast<std::size_t>(g.face)][static_cast<std::size_t>(g.i)] - B == tau)) {
        ++report.seam_mismatches;
        continue;
      }
      const I64 tk = tau.x / lattice_scale, tl = tau.y / lattice_scale;
      const auto [k0, k1] = cell_range(std::min(A.x, B.x), std::max(A.x, B.x));
      const auto [l0, l1] = cell_range(std::min(A.y, B.y), std::max(A.y, B.y));
      for (I64 k = k0; k <= k1; ++k)
        for (I64 l = l0; l <= l1; ++l) {
          if (!segment_meets_cell(A, B, k, l)) continue;
          const auto p = pieces.index.find({static_cast<int>(f), k, l});
          const auto r = pieces.index.find({g.face, k + tk, l + tl});
          if (p != pieces.index.end() && r != pieces.index.end()) cells.unite(p->second, r->second);
        }
    }
  }
  std::unordered_map<int, std::vector<int>> members;
  for (std::size_t p = 0; p < pieces.keys.size(); ++p)
    members[cells.find(static_cast<int>(p))].push_back(static_cast<int>(p));
  // deterministic order: by first piece
  std::vector<std::vector<int>> ordered;
  for (auto& [root, list] : members) ordered.push_back(std::move(list));
  std::sort(ordered.begin(), ordered.end(),
            [](const std::vector<int>& x, const std::vector<int>& y) { return x.front() < y.front(); });
  return ordered;
}

/// The quad points: lattice points located in a piece's closed triangle, one
/// point per place on S whatever the chart (the key: a vertex, an edge and the
/// offset from its smaller end, or a face and the offset from its first corner).
class LatticePoints {
 public:
  LatticePoints(const TriangleSoup& soup, const Charts& q, LatticeQuads& out) : soup_(soup), q_(q), out_(out) {}

  /// The corner (piece.k + dx, piece.l + dy) of the piece's cell, if it lies in the
  /// piece's closed triangle: its point's id in `id`.
  bool locate(const CellKey& piece, int dx, int dy, int& id) {
    const auto f = static_cast<std::size_t>(piece.face);
    const auto& t = q_[f];
    const P2 L{(piece.k + dx) * lattice_scale, (piece.l + dy) * lattice_scale};
    int o[3];
    for (int i = 0; i < 3; ++i) {
      o[i] = orient(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)], L);
      if (o[i] < 0) return false;
    }
    SurfaceLocation loc;
    loc.face = piece.face;
    const PointKey key = place(piece, L, o, loc);
    const auto it = point_of_.find(key);
    if (it != point_of_.end()) {
      id = it->second;
      return true;
    }
    id = static_cast<int>(out_.points.size());
    point_of_.emplace(key, id);
    const Triangle& tri = soup_.triangles[f];
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < 3; ++i)
      p += loc.barycentric[static_cast<std::size_t>(i)] * soup_.points[static_cast<std::size_t>(tri[i])];
    out_.points.push_back(p);
    out_.locations.push_back(loc);
    return true;
  }

 private:
  /// Where the lattice point L (in the piece's triangle, edge orientations `o`,
  /// none negative) lies on S: `loc`'s kind, ends and barycentric coordinates, and its key.
  PointKey place(const CellKey& piece, P2 L, const int (&o)[3], SurfaceLocation& loc) const {
    const auto& t = q_[static_cast<std::size_t>(piece.face)];
    const Triangle& tri = soup_.triangles[static_cast<std::size_t>(piece.face)];
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    if (zeros >= 2) {
      int corner = 0;
      while (!(L == t[static_cast<std::size_t>(corner)])) ++corner;
      loc.kind = SurfaceLocation::Kind::vertex;
      loc.a = tri[corner];
      loc.barycentric[static_cast<std::size_t>(corner)] = 1.0;
      return {0, loc.a, 0, 0, 0};
    }
    // barycentric coordinates from the exact sub-areas
    double w[3], sum = 0;
    for (int i = 0; i < 3; ++i) {
      const P2 u = t[static_cast<std::size_t>((i + 1) % 3)], v = t[static_cast<std::size_t>((i + 2) % 3)];
      w[i] = static_cast<double>(I128(u.x - L.x) * I128(v.y - L.y) - I128(u.y - L.y) * I128(v.x - L.x));
      sum += w[i];
    }
    for (int i = 0; i < 3; ++i) loc.barycentric[static_cast<std::size_t>(i)] = w[i] / sum;
    if (zeros == 1) {
      int e = 0;
      while (o[e] != 0) ++e;
      const int a = tri[e], b = tri[(e + 1) % 3];
      const int low = a < b ? e : (e + 1) % 3;
      const P2 offset = L - t[static_cast<std::size_t>(low)];
      loc.kind = SurfaceLocation::Kind::edge;
      loc.a = std::min(a, b);
      loc.b = std::max(a, b);
      return {1, loc.a, loc.b, offset.x, offset.y};
    }
    const P2 offset = L - t[0];
    loc.kind = SurfaceLocation::Kind::face;
    return {2, piece.face, 0, offset.x, offset.y};
  }

  const TriangleSoup& soup_;
  const Charts& q_;
  LatticeQuads& out_;
  std::map<PointKey, int> point_of_;
};

/// The quad of a complete cell (its pieces `cell`): its four corners, each located
/// in the first piece that holds it, counter-clockwise from (k, l). Nothing when a
/// corner is not found or two are one point.
std::optional<std::array<int, 4>> cell_quad(const std::vector<int>& cell, const Pieces& pieces, LatticePoints& points) {
  static constexpr int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::array<int, 4> quad{-1, -1, -1, -1};
  for (int c = 0; c < 4; ++c) {
    bool found = false;
    for (int p : cell)
      if (points.locate(pieces.keys[static_cast<std::size_t>(p)], offsets[c][0], offsets[c][1],
                        quad[static_cast<std::size_t>(c)])) {
        found = true;
        break;
      }
    if (!found) return std::nullopt;
  }
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (quad[static_cast<std::size_t>(i)] == quad[static_cast<std::size_t>(j)]) return std::nullopt;
  return quad;
}

}  // namespace

LatticeQuads extract_lattice_quads(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                   const FaceMap& param, ExtractionReport& report) {
  report = {};
  // 1. fixed-point charts, integer translations between the charts of a vertex
  const Charts q = fixed_point_charts(soup, param, report);
  const std::vector<char> good = usable_triangles(q, report);
  // 2. pieces; 3. pieces across edges
  const Pieces pieces = cell_pieces(q, good);
  const std::vector<std::vector<int>> cells = join_pieces(soup, adjacency, q, good, pieces, report);
  // 4. cells: complete ones become quads
  LatticeQuads out;
  LatticePoints points(soup, q, out);
  const auto problem_at = [&](int first_piece) {
    if (report.first_problem_triangle < 0) report.first_problem_triangle = pieces.keys[static_cast<std::size_t>(first_piece)].face;
  };
  for (const std::vector<int>& cell : cells) {
    double area = 0;
    for (int p : cell) area += pieces.area[static_cast<std::size_t>(p)];
    if (std::abs(area - 1.0) > complete_cell_tolerance) {
      ++report.incomplete_cells;
      problem_at(cell.front());
      continue;
    }
    const auto quad = cell_quad(cell, pieces, points);
    if (!quad) {
      ++report.degenerate_cells;
      problem_at(cell.front());
      continue;
    }
    out.quads.push_back(*quad);
  }
  report.cells = out.quads.size();
  return out;
}

PolygonMesh polygon_mesh(const LatticeQuads& quads) {
  PolygonMesh mesh;
  mesh.points = quads.points;
  for (const auto& quad : quads.quads) mesh.faces.push_back({quad[0], quad[1], quad[2], quad[3]});
  return mesh;
}

std::array<Vec3, 4> quad_corners(const LatticeQuads& quads, std::size_t k) {
  const std::array<int, 4>& q = quads.quads[k];
  return {quads.points[static_cast<std::size_t>(q[0])], quads.points[static_cast<std::size_t>(q[1])],
          quads.points[static_cast<std::size_t>(q[2])], quads.points[static_cast<std::size_t>(q[3])]};
}

std::array<Vec3, 4> quad_corners(const LatticeQuads& quads, std::size_t k, int v, const Vec3& p) {
  std::array<Vec3, 4> c = quad_corners(quads, k);
  for (std::size_t i = 0; i < 4; ++i)
    if (quads.quads[k][i] == v) c[i] = p;
  return c;
}

std::vector<int> stray_boundary_points(const LatticeQuads& quads, const std::vector<int>& boundary_loop_of_point) {
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  std::map<std::pair<int, int>, int> uses;
  for (const auto& quad : quads.quads)
    for (std::size_t k = 0; k < 4; ++k) ++uses[std::minmax(quad[k], quad[(k + 1) % 4])];
  std::vector<char> stray(quads.points.size(), 0);
  for (const auto& [edge, count] : uses)
    if (count == 1)
      for (const int v : {edge.first, edge.second})
        if (boundary_loop_of_point[static_cast<std::size_t>(v)] < 0) stray[static_cast<std::size_t>(v)] = 1;
  std::vector<int> out;
  for (std::size_t v = 0; v < stray.size(); ++v)
    if (stray[v]) out.push_back(static_cast<int>(v));
  return out;
}

}  // namespace qm
