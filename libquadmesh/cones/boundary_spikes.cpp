#include "libquadmesh/cones/boundary_spikes.h"

#include "libquadmesh/cones/boundary_corners.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/topology/internal/soup_cleaning.h"

#include <cmath>
#include <vector>

namespace qm {

namespace {

/// A clipped base can leave a new spike at its ends; a few passes are enough.
constexpr int max_spike_passes = 4;

/// The triangles round the spikes (clip_boundary_spikes), in order.
std::vector<int> spike_triangles(const TriangleSoup& soup, double quad) {
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  std::vector<char> corner(soup.points.size(), 0);
  for (const BoundaryCorner& c : boundary_corners(soup, corner_window_quads * quad))
    corner[static_cast<std::size_t>(c.vertex)] = 1;
  std::vector<char> touched(soup.points.size(), 0);  // points of the triangles clipped in this pass
  std::vector<int> out;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (!adjacency.boundary_vertex[v] || corner[v]) continue;
    const std::vector<int>& faces = adjacency.vertex_faces[v];
    // the corner's angle first: most boundary vertices are no spike
    double angle = 0;
    for (int f : faces) {
      const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
      int k = 0;
      while (t[static_cast<std::size_t>(k)] != static_cast<int>(v)) ++k;
      angle += corner_angle(soup, static_cast<std::size_t>(f), k);
    }
    if (angle * 180 / M_PI >= spike_angle_deg) continue;
    const auto loop = static_cast<std::size_t>(adjacency.loop_of_vertex[v]);
    bool fits = adjacency.boundary_loops[loop].size() > 3 && !touched[v];
    // every edge at v short, every inner one ending off the boundary (clipping would
    // pinch the surface there), no point shared with a spike clipped in this pass
    for (int f : faces) {
      const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
      for (int p : t) {
        const auto pi = static_cast<std::size_t>(p);
        if (pi == v) continue;
        fits = fits && !touched[pi] && (soup.points[pi] - soup.points[v]).norm() < quad &&
               (adjacency.is_boundary_edge(static_cast<int>(v), p) || !adjacency.boundary_vertex[pi]);
      }
    }
    if (!fits) continue;
    for (int f : faces) {
      for (int p : soup.triangles[static_cast<std::size_t>(f)]) touched[static_cast<std::size_t>(p)] = 1;
      out.push_back(f);
    }
  }
  return out;
}

}  // namespace

std::size_t clip_boundary_spikes(TriangleSoup& soup, double quad) {
  QM_ASSERT(quad > 0);
  std::size_t removed = 0;
  for (int pass = 0; pass < max_spike_passes; ++pass) {
    const std::vector<int> spikes = spike_triangles(soup, quad);
    if (spikes.empty()) break;
    std::vector<char> drop(soup.triangles.size(), 0);
    for (int f : spikes) drop[static_cast<std::size_t>(f)] = 1;
    std::vector<int> keep;
    for (std::size_t f = 0; f < soup.triangles.size(); ++f)
      if (!drop[f]) keep.push_back(static_cast<int>(f));
    soup = sub_soup(soup, keep);
    removed += spikes.size();
  }
  return removed;
}

}  // namespace qm
