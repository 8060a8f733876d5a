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

/// r modulo 4, in 0..3.
int quarter(int r) { return ((r % 4) + 4) % 4; }

/// i^r z, exactly: a quarter turn only swaps and negates coordinates.
Complex turned(Complex z, int r) {
  switch (quarter(r)) {
    case 1: return {-z.imag(), z.real()};
    case 2: return {-z.real(), -z.imag()};
    case 3: return {z.imag(), -z.real()};
    default: return z;
  }
}

/// The fixed-point point p turned by r quarter turns about the origin: (x, y) -> (-y, x) per turn.
P2 turned(P2 p, int r) {
  switch (quarter(r)) {
    case 1: return {-p.y, p.x};
    case 2: return {-p.x, -p.y};
    case 3: return {p.y, -p.x};
    default: return p;
  }
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

/// The cell that the cell (k, l) becomes under z -> i^r z + (tk, tl): the image of
/// the square [k, k+1] x [l, l+1] (one turn maps it to [-l-1, -l] x [k, k+1]).
std::pair<I64, I64> turned_cell(I64 k, I64 l, int r, I64 tk, I64 tl) {
  switch (quarter(r)) {
    case 1: return {-l - 1 + tk, k + tl};
    case 2: return {-k - 1 + tk, -l - 1 + tl};
    case 3: return {l + tk, -k - 1 + tl};
    default: return {k + tk, l + tl};
  }
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
  I128 x, y;
  bool operator<(const PointKey& o) const {
    return std::tie(kind, a, b, x, y) < std::tie(o.kind, o.a, o.b, o.x, o.y);
  }
};

/// Charts of two triangles at a vertex whose difference (after the quarter turn
/// between them) is farther than this (lattice units, per coordinate) from an
/// integer count as a seam mismatch.
constexpr double seam_tolerance = 1e-4;
/// A quarter turn replaces the chart's turn found so far across an edge only when it
/// maps one edge image closer to the other by more than this (lattice units): the
/// round-off of a translation-only map never turns a chart.
constexpr double quarter_turn_roundoff = 1e-9;
/// A cell is complete when its pieces' image areas add up to 1 within this
/// (lattice units^2); the areas are clipped in floating point.
constexpr double complete_cell_tolerance = 1e-6;

using Charts = std::vector<std::array<P2, 3>>;

/// The corner of triangle t at vertex v (precondition: t holds v).
int corner_of(const Triangle& t, int v) {
  int i = 0;
  while (t[i] != v) ++i;
  return i;
}

/// The quarter turns r (0..3) between two charts of one edge, whose images are
/// `from` and `to`: the r for which i^r from is nearest to `to` (method.md section
/// 11: charts differ by i^r z + t, so edge images by i^r).
int quarter_turns(Complex from, Complex to) {
  int best = 0;
  double best_distance = std::abs(to - from);
  for (int r = 1; r < 4; ++r) {
    const double d = std::abs(to - turned(from, r));
    if (d < best_distance - quarter_turn_roundoff) {
      best = r;
      best_distance = d;
    }
  }
  return best;
}

/// The turn (quarter turns) of the chart of each face around v, relative to the
/// chart of `reference` (a face at v): walking v's ring, the chart turns across the
/// edge v->w shared by two faces by quarter_turns(image of v->w before, after). At
/// a cone the turns around v add up to its holonomy, not 0; the walk starts at the
/// ring's first face and does not cross the edge between its last and first faces.
/// Returns (face, turn) pairs; a face off the ring (a non-manifold vertex) has turn 0.
/// `holonomy` gets the turns around an inner v (0 unless v is a cone; 0 on the
/// boundary).
std::vector<std::pair<int, int>> chart_turns_around(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                                    const FaceMap& param, int v, int reference, int& holonomy) {
  const VertexRing ring = vertex_ring(soup, adjacency, v);
  const auto image = [&](int f, int w) {
    const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
    const CornerValues& z = param.corners[static_cast<std::size_t>(f)];
    return z[static_cast<std::size_t>(corner_of(t, w))] - z[static_cast<std::size_t>(corner_of(t, v))];
  };
  std::vector<std::pair<int, int>> turns;
  int turn = 0;
  for (std::size_t k = 0; k < ring.faces.size(); ++k) {
    if (k > 0) {
      const int w = ring.neighbours[k];  // faces[k - 1] and faces[k] share v->w
      turn += quarter_turns(image(ring.faces[k - 1], w), image(ring.faces[k], w));
    }
    turns.push_back({ring.faces[k], turn});
  }
  holonomy = 0;
  if (!ring.boundary && !ring.faces.empty())
    holonomy = quarter(turn + quarter_turns(image(ring.faces.back(), ring.neighbours.front()),
                                            image(ring.faces.front(), ring.neighbours.front())));
  int reference_turn = 0;
  for (const auto& [f, r] : turns)
    if (f == reference) reference_turn = r;
  for (auto& [f, r] : turns) r = quarter(r - reference_turn);
  for (int f : adjacency.vertex_faces[static_cast<std::size_t>(v)])
    if (std::none_of(turns.begin(), turns.end(), [&](const std::pair<int, int>& fr) { return fr.first == f; }))
      turns.push_back({f, 0});
  return turns;
}

/// The fixed-point image of every triangle corner: the first chart met at each
/// vertex (by triangle order) is its reference, rounded to fixed point; every other
/// corner is that turned by its chart's quarter turns (chart_turns_around) plus an
/// integer translation, so that a lattice point on a seam is exactly the same in
/// every chart. Counts the corners whose translation is not an integer (within
/// seam_tolerance) as seam mismatches.
Charts fixed_point_charts(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& param,
                          ExtractionReport& report) {
  const double S = static_cast<double>(lattice_scale);
  Charts q(soup.triangles.size());
  for (std::size_t v = 0; v < adjacency.vertex_faces.size(); ++v) {
    const std::vector<int>& faces = adjacency.vertex_faces[v];
    if (faces.empty()) continue;
    const int reference_face = *std::min_element(faces.begin(), faces.end());
    const int vi = static_cast<int>(v);
    const Complex reference_value = param.corners[static_cast<std::size_t>(reference_face)][static_cast<std::size_t>(
        corner_of(soup.triangles[static_cast<std::size_t>(reference_face)], vi))];
    int holonomy = 0;
    const auto turns = chart_turns_around(soup, adjacency, param, vi, reference_face, holonomy);
    // a cone is the fixed point of its charts' turns: only a lattice point is
    // turned onto itself exactly, so its reference is that lattice point; so is
    // that of any vertex on a lattice point whose charts turn (a lattice point a
    // rounding off would land on different sides of it in different charts)
    const Complex snapped(std::round(reference_value.real()), std::round(reference_value.imag()));
    const bool on_lattice = std::abs(reference_value - snapped) <= seam_tolerance;
    const bool turning = holonomy != 0 || std::any_of(turns.begin(), turns.end(),
                                                      [](const std::pair<int, int>& fr) { return fr.second != 0; });
    const P2 reference = turning && on_lattice
                             ? P2{static_cast<I64>(snapped.real()) * lattice_scale, static_cast<I64>(snapped.imag()) * lattice_scale}
                             : P2{std::llround(reference_value.real() * S), std::llround(reference_value.imag() * S)};
    for (const auto& [f, r] : turns) {
      const auto i = static_cast<std::size_t>(corner_of(soup.triangles[static_cast<std::size_t>(f)], vi));
      const Complex diff = param.corners[static_cast<std::size_t>(f)][i] - turned(reference_value, r);
      const double dx = std::round(diff.real()), dy = std::round(diff.imag());
      if (std::abs(diff.real() - dx) > seam_tolerance || std::abs(diff.imag() - dy) > seam_tolerance)
        ++report.seam_mismatches;
      q[static_cast<std::size_t>(f)][i] =
          turned(reference, r) + P2{static_cast<I64>(dx) * lattice_scale, static_cast<I64>(dy) * lattice_scale};
    }
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

/// The map z_g = i^r z_f + tau from the chart of a triangle f to that of its
/// neighbour g across an edge (fixed point; tau a lattice vector).
struct Transition {
  int r = 0;
  P2 tau;
};

/// The transition of an edge whose images are A -> B in one chart and Ag -> Bg in
/// the other: the quarter turn that maps B - A onto Bg - Ag exactly, and the
/// translation then left. Nothing when there is none or the translation is not a
/// lattice vector (a seam mismatch). Precondition: A != B.
std::optional<Transition> edge_transition(P2 A, P2 B, P2 Ag, P2 Bg) {
  for (int r = 0; r < 4; ++r)
    if (turned(B - A, r) == Bg - Ag) {
      const P2 tau = Ag - turned(A, r);
      if (tau.x % lattice_scale != 0 || tau.y % lattice_scale != 0) return std::nullopt;
      return Transition{r, tau};
    }
  return std::nullopt;
}

/// A cell: its pieces (ascending) and the turn of each piece's chart relative to the
/// first piece's (piece chart = i^turn first chart + a lattice vector).
struct Cell {
  std::vector<int> pieces;
  std::vector<int> turns;
  bool consistent = true;  ///< false: two paths between pieces disagree on a turn (a cone inside)
};

/// The turns of a cell's pieces relative to its first, by a breadth-first walk over
/// the joins (`joins[p]`: (piece, turn from p's chart to its chart)).
void turn_cell_pieces(Cell& cell, const std::vector<std::vector<std::pair<int, int>>>& joins) {
  std::unordered_map<int, int> turn_of{{cell.pieces.front(), 0}};
  std::vector<int> queue{cell.pieces.front()};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int p = queue[head];
    for (const auto& [next, r] : joins[static_cast<std::size_t>(p)]) {
      const int turn = quarter(turn_of[p] + r);
      const auto [it, added] = turn_of.emplace(next, turn);
      if (added)
        queue.push_back(next);
      else if (it->second != turn)
        cell.consistent = false;
    }
  }
  for (int p : cell.pieces) cell.turns.push_back(turn_of[p]);
}

/// The cells: the pieces of two usable triangles sharing an edge are one cell
/// where the open edge crosses the open cell (mapped by the edge's transition, a
/// quarter turn and a lattice translation). Counts the edges whose two charts
/// differ by more than that as seam mismatches. Returns the cells ordered by their
/// first piece.
std::vector<Cell> join_pieces(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Charts& q,
                              const std::vector<char>& good, const Pieces& pieces, ExtractionReport& report) {
  UnionFind cells(pieces.keys.size());
  std::vector<std::vector<std::pair<int, int>>> joins(pieces.keys.size());
  for (std::size_t f = 0; f < q.size(); ++f) {
    if (!good[f]) continue;
    for (int i = 0; i < 3; ++i) {
      const int a = soup.triangles[f][i], b = soup.triangles[f][(i + 1) % 3];
      const EdgeCorner g = adjacency.find(b, a);
      if (g.face < 0 || static_cast<std::size_t>(g.face) < f || !good[static_cast<std::size_t>(g.face)]) continue;
      const auto& tg = q[static_cast<std::size_t>(g.face)];
      const P2 A = q[f][static_cast<std::size_t>(i)], B = q[f][static_cast<std::size_t>((i + 1) % 3)];
      const auto transition =
          edge_transition(A, B, tg[static_cast<std::size_t>(g.j)], tg[static_cast<std::size_t>(g.i)]);
      if (!transition) {
        ++report.seam_mismatches;
        continue;
      }
      const I64 tk = transition->tau.x / lattice_scale, tl = transition->tau.y / lattice_scale;
      const auto [k0, k1] = cell_range(std::min(A.x, B.x), std::max(A.x, B.x));
      const auto [l0, l1] = cell_range(std::min(A.y, B.y), std::max(A.y, B.y));
      for (I64 k = k0; k <= k1; ++k)
        for (I64 l = l0; l <= l1; ++l) {
          if (!segment_meets_cell(A, B, k, l)) continue;
          const auto [kg, lg] = turned_cell(k, l, transition->r, tk, tl);
          const auto p = pieces.index.find({static_cast<int>(f), k, l});
          const auto r = pieces.index.find({g.face, kg, lg});
          if (p == pieces.index.end() || r == pieces.index.end()) continue;
          cells.unite(p->second, r->second);
          joins[static_cast<std::size_t>(p->second)].push_back({r->second, transition->r});
          joins[static_cast<std::size_t>(r->second)].push_back({p->second, quarter(-transition->r)});
        }
    }
  }
  std::unordered_map<int, std::vector<int>> members;
  for (std::size_t p = 0; p < pieces.keys.size(); ++p)
    members[cells.find(static_cast<int>(p))].push_back(static_cast<int>(p));
  // deterministic order: by first piece
  std::vector<Cell> ordered;
  for (auto& [root, list] : members) ordered.push_back(Cell{std::move(list), {}, true});
  std::sort(ordered.begin(), ordered.end(),
            [](const Cell& x, const Cell& y) { return x.pieces.front() < y.pieces.front(); });
  for (Cell& cell : ordered) turn_cell_pieces(cell, joins);
  return ordered;
}

/// The quad points: lattice points located in a piece's closed triangle, one
/// point per place on S whatever the chart (the key: a vertex; an edge and the dot
/// product of the offset from its smaller end with the edge, which neither a quarter
/// turn nor a translation of the chart changes; or a face and the offset from its
/// first corner, a face having one chart).
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
      const P2 edge = t[static_cast<std::size_t>(low == e ? (e + 1) % 3 : e)] - t[static_cast<std::size_t>(low)];
      loc.kind = SurfaceLocation::Kind::edge;
      loc.a = std::min(a, b);
      loc.b = std::max(a, b);
      // offset . edge: the place along the edge, the same in charts turned or moved
      return {1, loc.a, loc.b, I128(offset.x) * I128(edge.x) + I128(offset.y) * I128(edge.y), 0};
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

/// The quad of a complete cell: its four corners, counter-clockwise from (k, l) of
/// the first piece's chart, each located in the first piece that holds it. Corner c
/// of the first piece's cell is corner (c + turn) mod 4 of the cell of a piece whose
/// chart is turned by `turn` quarter turns (i^turn maps (k, l) to the corner after
/// it, counter-clockwise). Nothing when a corner is not found, two are one point, or
/// the pieces disagree on their turns.
std::optional<std::array<int, 4>> cell_quad(const Cell& cell, const Pieces& pieces, LatticePoints& points) {
  static constexpr int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  if (!cell.consistent) return std::nullopt;
  std::array<int, 4> quad{-1, -1, -1, -1};
  for (int c = 0; c < 4; ++c) {
    bool found = false;
    for (std::size_t j = 0; j < cell.pieces.size() && !found; ++j) {
      const auto& offset = offsets[quarter(c + cell.turns[j])];
      found = points.locate(pieces.keys[static_cast<std::size_t>(cell.pieces[j])], offset[0], offset[1],
                            quad[static_cast<std::size_t>(c)]);
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
  // 1. fixed-point charts: quarter turns and integer translations between the charts of a vertex
  const Charts q = fixed_point_charts(soup, adjacency, param, report);
  const std::vector<char> good = usable_triangles(q, report);
  // 2. pieces; 3. pieces across edges
  const Pieces pieces = cell_pieces(q, good);
  const std::vector<Cell> cells = join_pieces(soup, adjacency, q, good, pieces, report);
  // 4. cells: complete ones become quads
  LatticeQuads out;
  LatticePoints points(soup, q, out);
  const auto problem_at = [&](int first_piece) {
    if (report.first_problem_triangle < 0) report.first_problem_triangle = pieces.keys[static_cast<std::size_t>(first_piece)].face;
  };
  for (const Cell& cell : cells) {
    double area = 0;
    for (int p : cell.pieces) area += pieces.area[static_cast<std::size_t>(p)];
    if (std::abs(area - 1.0) > complete_cell_tolerance) {
      ++report.incomplete_cells;
      problem_at(cell.pieces.front());
      continue;
    }
    const auto quad = cell_quad(cell, pieces, points);
    if (!quad) {
      ++report.degenerate_cells;
      problem_at(cell.pieces.front());
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
