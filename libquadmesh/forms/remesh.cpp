#include "libquadmesh/forms/remesh.h"

#include "libquadmesh/core/mesh.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <iterator>

namespace qm {

namespace PMP = CGAL::Polygon_mesh_processing;

/// Without a target, the remeshed edges are this fraction of the input's mean edge.
constexpr double default_edge_fraction = 0.4;

double remesh_target(const TriangleSoup& soup, const RemeshOptions& options) {
  return options.target_edge_length > 0 ? options.target_edge_length : default_edge_fraction * mean_edge_length(soup);
}

TriangleSoup remesh_isotropic(const TriangleSoup& soup, const RemeshOptions& options) {
  const double target = remesh_target(soup, options);
  Mesh mesh = to_surface_mesh(soup);
  auto constrained = mesh.add_property_map<Mesh::Edge_index, bool>("e:boundary", false).first;
  std::vector<Mesh::Halfedge_index> border;
  PMP::border_halfedges(faces(mesh), mesh, std::back_inserter(border));
  std::vector<Mesh::Edge_index> border_edges;
  for (Mesh::Halfedge_index h : border) {
    constrained[mesh.edge(h)] = true;
    border_edges.push_back(mesh.edge(h));
  }
  // split the boundary first so that protected edges are not longer than the target
  PMP::split_long_edges(border_edges, target, mesh, PMP::parameters::edge_is_constrained_map(constrained));
  PMP::isotropic_remeshing(faces(mesh), target, mesh,
                           PMP::parameters::number_of_iterations(static_cast<unsigned>(options.iterations))
                               .edge_is_constrained_map(constrained)
                               .protect_constraints(true));
  mesh.collect_garbage();
  // every point is new: none carries the file's numbering (label -1)
  TriangleSoup out = soup_of(mesh, TriangleSoup{});
  return out;
}

}  // namespace qm
