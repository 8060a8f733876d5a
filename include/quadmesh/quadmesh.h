// quadmesh: boundary-aligned, near-orthogonal pure-quad meshes of triangulated
// surfaces with boundary (chi < 0: plates with holes, pairs of pants, handled
// surfaces with holes), from symmetric holomorphic differentials on the doubled
// surface (docs/method.md). The one header a user includes; link quadmesh::core.
//
//   qm::QuadMeshOptions options;
//   options.size_relative = 0.015;  // quads 1.5% of the bounding-box diagonal
//   const qm::QuadMeshResult r = qm::mesh_quads(points, triangles, options);
//   // r.quads.points, r.quads.quads: the quads, counter-clockwise
//   const qm::QuadQuality q = qm::quad_quality(qm::polygon_mesh(r.quads), &r.surface);
//
// Failures are qm::Error (core/error.h), whose what() is one line naming the
// problem and where: ErrorCode::bad_input (not a valid manifold triangulation:
// the vertex or triangle is named), unsupported (a valid surface the method
// does not apply to: a disk, a sphere, several pieces), solver (a stage failed).
//
// The stages, for those who want them one at a time: analyze_topology and
// assess_applicability (topology/), symmetric_forms (forms/), quantize (param/),
// extract_lattice_quads (extract/), quad_quality and two_sided_hausdorff
// (quality/); quadratic_quads (extract/: 8- or 9-node quads with their nodes on
// r.surface) and curved_jacobians (quality/) for quadratic elements. Headers
// under an internal/ folder are the library's own helpers.
#pragma once

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"
#include "libquadmesh/extract/quadratic_quads.h"
#include "libquadmesh/pipeline/acceptance_criteria.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "libquadmesh/quality/curved_jacobian.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/topology/applicability.h"
#include "libquadmesh/topology/topology_report.h"

#include <vector>

namespace qm {

/// The whole job on a surface given as arrays: checks it (indices in range, then
/// analyze_topology and assess_applicability: finite coordinates in range, no
/// degenerate or duplicate triangle, manifold, one orientable piece with
/// boundary and chi <= 0), then meshes it with quads (mesh_quads on the soup).
///  - points: vertex positions; triangles: indices into points, 0-based, each
///    triangle counter-clockwise seen from the side the normals should face
///    (a consistent orientation is all that matters).
/// Returns the quads and every report of the stages (QuadMeshResult); throws
/// qm::Error as described at the top of this header. Never prints; progress,
/// when given, is called with the name of each stage as it starts.
QuadMeshResult mesh_quads(std::vector<Vec3> points, std::vector<Triangle> triangles,
                          const QuadMeshOptions& options = {}, const ProgressCallback& progress = {});

}  // namespace qm
