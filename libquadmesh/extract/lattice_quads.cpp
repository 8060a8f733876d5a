#include "libquadmesh/extract/lattice_quads.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/internal/union_find.h"

#include <algorithm>
#include <cmath>
#include <map>
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

}  // namespace

LatticeQuads extract_lattice_quads(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                   const FaceMap& param, ExtractionReport& report) {
  const std::size_t nF = soup.triangles.size(), nV = soup.points.size();
  const double S = static_cast<double>(lattice_scale);
  report = {};

  // 1. fixed-point charts, integer translations between the charts of a vertex
  std::vector<std::array<P2, 3>> q(nF);
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
      if (std::abs(diff.real() - dx) > 1e-4 || std::abs(diff.imag() - dy) > 1e-4) ++report.seam_mismatches;
      q[f][static_cast<std::size_t>(i)] =
          reference[v] + P2{static_cast<I64>(dx) * lattice_scale, static_cast<I64>(dy) * lattice_scale};
    }
  // a triangle is used when positive and not absurdly large (a map blown up by a
  // failed repair would otherwise have its lattice enumerated cell by cell)
  auto cells_spanned = [&](const std::array<P2, 3>& t) {
    const auto [k0, k1, l0, l1] = cell_box(t);
    return static_cast<double>(k1 - k0 + 1) * static_cast<double>(l1 - l0 + 1);
  };
  std::vector<char> good(nF, 0);
  for (std::size_t f = 0; f < nF; ++f) {
    good[f] = orient(q[f][0], q[f][1], q[f][2]) > 0 && cells_spanned(q[f]) <= max_cells_per_triangle;
    if (!good[f] && report.bad_triangles++ == 0) report.first_problem_triangle = static_cast<int>(f);
  }

  // 2. pieces
  std::vector<CellKey> pieces;
  std::vector<double> piece_area;
  std::unordered_map<CellKey, int, CellKeyHash> piece_of;
  for (std::size_t f = 0; f < nF; ++f) {
    if (!good[f]) continue;
    const auto& t = q[f];
    const auto [k0, k1, l0, l1] = cell_box(t);
    for (I64 k = k0; k <= k1; ++k)
      for (I64 l = l0; l <= l1; ++l)
        if (triangle_meets_cell(t, k, l)) {
          const CellKey key{static_cast<int>(f), k, l};
          piece_of.emplace(key, static_cast<int>(pieces.size()));
          pieces.push_back(key);
          piece_area.push_back(clipped_area(t, k, l));
        }
  }

  // 3. pieces across edges
  UnionFind cells(pieces.size());
  for (std::size_t f = 0; f < nF; ++f) {
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
          const auto p = piece_of.find({static_cast<int>(f), k, l});
          const auto r = piece_of.find({g.face, k + tk, l + tl});
          if (p != piece_of.end() && r != piece_of.end()) cells.unite(p->second, r->second);
        }
    }
  }

  // 4. cells: complete ones become quads
  std::unordered_map<int, std::vector<int>> members;
  for (std::size_t p = 0; p < pieces.size(); ++p) members[cells.find(static_cast<int>(p))].push_back(static_cast<int>(p));
  LatticeQuads out;
  std::map<PointKey, int> point_of;
  auto locate = [&](const CellKey& piece, int dx, int dy, int& id) {
    const auto f = static_cast<std::size_t>(piece.face);
    const auto& t = q[f];
    const P2 L{(piece.k + dx) * lattice_scale, (piece.l + dy) * lattice_scale};
    int o[3];
    for (int i = 0; i < 3; ++i) {
      o[i] = orient(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)], L);
      if (o[i] < 0) return false;
    }
    const Triangle& tri = soup.triangles[f];
    SurfaceLocation loc;
    loc.face = piece.face;
    PointKey key{};
    int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    if (zeros >= 2) {
      int corner = 0;
      while (!(L == t[static_cast<std::size_t>(corner)])) ++corner;
      loc.kind = SurfaceLocation::Kind::vertex;
      loc.a = tri[corner];
      loc.barycentric[static_cast<std::size_t>(corner)] = 1.0;
      key = {0, loc.a, 0, 0, 0};
    } else {
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
        key = {1, loc.a, loc.b, offset.x, offset.y};
      } else {
        const P2 offset = L - t[0];
        loc.kind = SurfaceLocation::Kind::face;
        key = {2, piece.face, 0, offset.x, offset.y};
      }
    }
    const auto it = point_of.find(key);
    if (it != point_of.end()) {
      id = it->second;
      return true;
    }
    id = static_cast<int>(out.points.size());
    point_of.emplace(key, id);
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < 3; ++i)
      p += loc.barycentric[static_cast<std::size_t>(i)] * soup.points[static_cast<std::size_t>(tri[i])];
    out.points.push_back(p);
    out.locations.push_back(loc);
    return true;
  };
  // deterministic order: by first piece
  std::vector<std::pair<int, const std::vector<int>*>> ordered;
  for (const auto& [root, list] : members) ordered.push_back({list.front(), &list});
  std::sort(ordered.begin(), ordered.end());
  for (const auto& [first, list] : ordered) {
    double area = 0;
    for (int p : *list) area += piece_area[static_cast<std::size_t>(p)];
    if (std::abs(area - 1.0) > 1e-6) {
      ++report.incomplete_cells;
      if (report.first_problem_triangle < 0) report.first_problem_triangle = pieces[static_cast<std::size_t>(first)].face;
      continue;
    }
    static constexpr int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::array<int, 4> quad{-1, -1, -1, -1};
    bool ok = true;
    for (int c = 0; c < 4 && ok; ++c) {
      bool found = false;
      for (int p : *list)
        if (locate(pieces[static_cast<std::size_t>(p)], offsets[c][0], offsets[c][1], quad[static_cast<std::size_t>(c)])) {
          found = true;
          break;
        }
      ok = found;
    }
    for (int i = 0; i < 4 && ok; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (quad[static_cast<std::size_t>(i)] == quad[static_cast<std::size_t>(j)]) ok = false;
    if (!ok) {
      ++report.degenerate_cells;
      if (report.first_problem_triangle < 0) report.first_problem_triangle = pieces[static_cast<std::size_t>(first)].face;
      continue;
    }
    out.quads.push_back(quad);
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
