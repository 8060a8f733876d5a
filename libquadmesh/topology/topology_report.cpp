#include "libquadmesh/topology/topology_report.h"

#include "libquadmesh/topology/internal/soup_cleaning.h"
#include "libquadmesh/topology/internal/vertex_fans.h"

namespace qm {

namespace {

std::vector<ComponentTopology> component_topology(const EdgeIncidence& inc,
                                                  const Components& comps,
                                                  const BoundaryLoops& boundary, bool orientable,
                                                  bool edge_manifold) {
  std::vector<ComponentTopology> out(static_cast<std::size_t>(comps.count));
  for (int c : comps.point_component)
    if (c >= 0) ++out[c].vertices;
  for (const auto& e : inc.edges) ++out[comps.point_component[e[0]]].edges;
  for (int c : comps.triangle_component) ++out[c].faces;
  std::vector<int> first_loop_of(static_cast<std::size_t>(boundary.component_count), -1);
  for (std::size_t l = 0; l < boundary.loops.size(); ++l)
    if (first_loop_of[boundary.loop_component[l]] < 0) {
      first_loop_of[boundary.loop_component[l]] = static_cast<int>(l);
      ++out[comps.point_component[boundary.loops[l].front()]].boundary_loops;
    }
  for (auto& ct : out) {
    ct.euler_characteristic = static_cast<long>(ct.vertices) - static_cast<long>(ct.edges) +
                              static_cast<long>(ct.faces);
    const long twice_genus = 2 - ct.euler_characteristic - ct.boundary_loops;
    if (orientable && edge_manifold && twice_genus >= 0 && twice_genus % 2 == 0)
      ct.genus = static_cast<int>(twice_genus / 2);
  }
  return out;
}

}  // namespace

AnalyzedSurface analyze_topology(TriangleSoup soup) {
  AnalyzedSurface out;
  TopologyReport& r = out.report;
  r.points_read = soup.points.size();
  r.unreferenced_points = drop_unreferenced_points(soup);
  r.vertices = soup.points.size();
  r.faces = soup.triangles.size();

  r.nonfinite_vertices = nonfinite_points(soup);
  r.range = coordinate_range(soup);
  r.repeated_corner_faces = repeated_corner_triangles(soup);
  r.zero_area_faces = zero_area_triangles(soup);
  r.duplicate_faces = duplicate_triangles(soup);

  // Orient first: flipping a triangle renumbers its corners and halfedges, so the
  // incidence and the fans are built on the oriented soup.
  {
    const EdgeIncidence input_inc = edge_incidence(soup);
    r.orientation = orient_consistently(soup, input_inc);
    if (r.orientation.contradicting_edge >= 0)
      r.nonorientable_edge = input_inc.edges[r.orientation.contradicting_edge];
  }
  if (r.orientation.orientable && r.orientation.flip_count > 0)
    apply_orientation(soup, r.orientation.flip);

  const EdgeIncidence inc = edge_incidence(soup);
  r.edges = inc.edge_count();
  for (std::size_t e = 0; e < inc.edge_count(); ++e)
    if (!inc.is_manifold(static_cast<int>(e)))
      r.nonmanifold_edges.push_back({inc.edges[e][0], inc.edges[e][1], inc.valence(static_cast<int>(e))});
  const VertexFans fans = vertex_fans(soup, inc);
  for (std::size_t p = 0; p < soup.points.size(); ++p)
    if (fans.fans_per_point[p] > 1) r.nonmanifold_vertices.push_back(static_cast<int>(p));

  r.boundary = boundary_loops(soup, inc, fans);
  r.components = connected_components(soup);
  r.per_component = component_topology(inc, r.components, r.boundary,
                                       r.orientation.orientable, r.edge_manifold());

  r.euler_characteristic =
      static_cast<long>(r.vertices) - static_cast<long>(r.edges) + static_cast<long>(r.faces);
  r.genus = 0;
  for (const auto& ct : r.per_component) {
    if (ct.genus < 0) {
      r.genus = -1;
      break;
    }
    r.genus += ct.genus;
  }
  if (r.per_component.empty()) r.genus = -1;
  out.soup = std::move(soup);
  return out;
}

}  // namespace qm
