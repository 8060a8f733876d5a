#include "libquadmesh/param/untangle.h"

#include <set>

namespace qm {

std::size_t count_flipped(const FaceMap& param) {
  std::size_t n = 0;
  for (const CornerValues& c : param.corners) n += image_area2(c) <= 0;
  return n;
}

UntangleReport unmoved_report(const FaceMap& param) {
  UntangleReport report;
  report.flipped_before = count_flipped(param);
  report.flipped_after = report.flipped_before;
  return report;
}

namespace {

/// The polygon `poly` clipped to the half-plane left of the line a->b.
std::vector<Complex> clip_left(const std::vector<Complex>& poly, Complex a, Complex b) {
  auto side = [&](Complex p) { return std::imag(std::conj(b - a) * (p - a)); };
  std::vector<Complex> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Complex p = poly[i], q = poly[(i + 1) % poly.size()];
    const double sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return out;
}

Complex centroid(const std::vector<Complex>& poly, double& area) {
  Complex c = 0;
  area = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Complex p = poly[i], q = poly[(i + 1) % poly.size()];
    const double cross = std::imag(std::conj(p) * q);
    area += cross;
    c += (p + q) * cross;
  }
  area *= 0.5;
  return std::abs(area) > 0 ? c / (6 * area) : Complex(0, 0);
}

}  // namespace

/// Sweeps at most; the first own_star_sweeps move only the vertices of folded
/// triangles (later ones their neighbours too), and the cones' stars (pinned 2)
/// move only after pinned_star_sweeps.
constexpr int max_sweeps = 100;
constexpr int own_star_sweeps = 10;
constexpr int pinned_star_sweeps = 20;

UntangleReport untangle(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, FaceMap& param,
                        const std::vector<char>& pinned) {
  UntangleReport report = unmoved_report(param);
  auto shift_vertex = [&](int v, Complex by) {
    for (int f : adjacency.vertex_faces[static_cast<std::size_t>(v)])
      for (int i = 0; i < 3; ++i)
        if (soup.triangles[static_cast<std::size_t>(f)][i] == v) param.corners[static_cast<std::size_t>(f)][i] += by;
  };
  // pinned 1: never moves; 2: moves only after pinned_star_sweeps sweeps
  auto movable = [&](int v, int sweep) {
    const char p = pinned[static_cast<std::size_t>(v)];
    return p == 0 || (p == 2 && sweep > pinned_star_sweeps);
  };
  std::set<int> moved;
  for (int sweep = 1; sweep <= max_sweeps && report.flipped_after > 0; ++sweep) {
    report.rounds = sweep;
    std::set<int> candidates;
    for (std::size_t f = 0; f < soup.triangles.size(); ++f)
      if (image_area2(param.corners[f]) <= 0)
        for (int v : soup.triangles[f])
          if (movable(v, sweep)) candidates.insert(v);
    // later sweeps also move the neighbours, whose kernels may be wider
    if (sweep > own_star_sweeps) {
      std::set<int> grown = candidates;
      for (int v : candidates)
        for (int f : adjacency.vertex_faces[static_cast<std::size_t>(v)])
          for (int u : soup.triangles[static_cast<std::size_t>(f)])
            if (movable(u, sweep)) grown.insert(u);
      candidates.swap(grown);
    }
    for (int v : candidates) {
      const VertexRing ring = vertex_ring(soup, adjacency, v);
      std::vector<Complex> link;  // relative to v's image
      for (int u : ring.neighbours) link.push_back(edge_value(adjacency, param, v, u));
      const std::size_t n = link.size();
      const std::size_t edges = ring.boundary ? n - 1 : n;
      Complex target;
      if (ring.boundary) {
        // v stays on its boundary line (imaginary part 0): an interval of U
        double lo = -1e300, hi = 1e300;
        for (std::size_t k = 0; k < edges; ++k) {
          const Complex a = link[k], b = link[(k + 1) % n];
          // left of a->b at p = x: Im(conj(b - a) (x - a)) > 0, linear in x
          const Complex d = b - a;
          const double slope = std::imag(std::conj(d) * Complex(1, 0));
          const double offset = std::imag(std::conj(d) * (-a));
          if (slope > 0) lo = std::max(lo, -offset / slope);
          else if (slope < 0) hi = std::min(hi, -offset / slope);
          else if (offset <= 0) hi = lo - 1;  // never satisfied
        }
        if (!(lo < hi) || lo < -1e299 || hi > 1e299) continue;
        target = Complex(0.5 * (lo + hi), 0);
      } else {
        double radius = 0;
        for (const Complex& p : link) radius = std::max(radius, std::abs(p));
        std::vector<Complex> kernel{Complex(-2 * radius, -2 * radius), Complex(2 * radius, -2 * radius),
                                    Complex(2 * radius, 2 * radius), Complex(-2 * radius, 2 * radius)};
        for (std::size_t k = 0; k < edges && !kernel.empty(); ++k) kernel = clip_left(kernel, link[k], link[(k + 1) % n]);
        if (kernel.size() < 3) continue;
        double area = 0;
        target = centroid(kernel, area);
        if (area <= 0) continue;
      }
      shift_vertex(v, target);
      moved.insert(v);
    }
    report.flipped_after = count_flipped(param);
  }
  report.moved_vertices = moved.size();
  return report;
}

}  // namespace qm
