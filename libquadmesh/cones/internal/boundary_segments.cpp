#include "libquadmesh/cones/internal/boundary_segments.h"

#include "libquadmesh/cones/internal/face_geometry.h"

#include <cmath>
#include <map>

namespace qm {

namespace {

/// A length within this of a whole number is taken as fixed by integer lines.
constexpr double whole_tolerance = 1e-6;

}  // namespace

BoundarySegments boundary_segments(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                   const CrossField& field, const CutGraph& cut, const std::vector<int>& quads,
                                   const std::vector<Complex>& scale) {
  BoundarySegments out;
  for (const std::vector<int>& loop : adjacency.boundary_loops) {
    const std::size_t n = loop.size();
    std::size_t start = 0;
    while (start < n && quads[static_cast<std::size_t>(loop[start])] == 2) ++start;
    if (start == n) continue;
    std::vector<SegmentEdge> run;
    double target = 0;
    for (std::size_t s = 0; s < n; ++s) {
      const int a = loop[(start + s) % n], b = loop[(start + s + 1) % n];
      const EdgeCorner e = adjacency.find(a, b);
      const auto f = static_cast<std::size_t>(e.face);
      const auto i = static_cast<std::size_t>(e.i), j = static_cast<std::size_t>(e.j);
      const CornerValues x = local_corners(soup, f);
      const Complex d = scale[f] * (x[j] - x[i]);
      SegmentEdge edge;
      edge.wedge_from = cut.wedge[f][i];
      edge.wedge_to = cut.wedge[f][j];
      edge.along = field.boundary_axis[f][i] == 0 ? 0 : 1;
      const double along_target = edge.along == 0 ? d.real() : d.imag();
      edge.sign = along_target >= 0 ? 1 : -1;
      target += std::abs(along_target);
      run.push_back(edge);
      if (quads[static_cast<std::size_t>(b)] != 2) {
        out.segments.push_back(std::move(run));
        out.target_length.push_back(target);
        run.clear();
        target = 0;
      }
    }
  }
  return out;
}

double segment_length(const BoundarySegments& segments, std::size_t s, const Eigen::VectorXd& z) {
  double length = 0;
  for (const SegmentEdge& e : segments.segments[s])
    length += e.sign * (z[2 * e.wedge_to + e.along] - z[2 * e.wedge_from + e.along]);
  return length;
}

std::vector<std::size_t> short_segments(const BoundarySegments& segments) {
  std::vector<std::size_t> out;
  for (std::size_t s = 0; s < segments.segments.size(); ++s)
    if (segments.target_length[s] < short_segment_length) out.push_back(s);
  return out;
}

std::vector<std::pair<int, double>> segment_terms(const BoundarySegments& segments, std::size_t s) {
  std::map<int, double> sum;
  for (const SegmentEdge& e : segments.segments[s]) {
    sum[2 * e.wedge_to + e.along] += e.sign;
    sum[2 * e.wedge_from + e.along] -= e.sign;
  }
  std::vector<std::pair<int, double>> out;
  for (const auto& [variable, coefficient] : sum)
    if (coefficient != 0) out.push_back({variable, coefficient});
  return out;
}

std::size_t collapsed_segments(const BoundarySegments& segments, const Eigen::VectorXd& z) {
  std::size_t collapsed = 0;
  for (std::size_t s = 0; s < segments.segments.size(); ++s) {
    const double length = segment_length(segments, s, z);
    collapsed += length < 0.5 && std::abs(length - std::round(length)) < whole_tolerance;
  }
  return collapsed;
}

}  // namespace qm
