// The steps `quadmesh mesh` takes around the mesher, shared by the one-surface
// run (cmd_mesh.cpp) and the run over an assembly's parts (cmd_mesh_parts.cpp).
#pragma once

#include "io/read_surface.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "tools/quadmesh/commands.h"
#include "tools/quadmesh/quad_output.h"

namespace qm::tools {

/// Before any work: -o and --report writable, and neither the input nor each
/// other (README "Exit codes": 2). Throws UsageError.
void check_mesh_files(const MeshOptions& options);

/// The work limit, once the input is read and before the forms: the quad count
/// --size implies (area / size^2, as mesh_quads scales h) against --max-quads.
void check_quad_estimate(const MeshOptions& options, const TriangleSoup& soup);

/// CAD input is triangulated at a third of the quad size while it is read: a
/// size far too small would keep Gmsh meshing for ever before the estimate above
/// is made. A coarse triangulation first (a tenth of the diagonal) gives the
/// area for the same estimate (`read`: the options of the real reading).
void check_cad_quad_estimate(const MeshOptions& options, const io::ReadOptions& read);

/// How the input is read for `quadmesh mesh`: the CAD triangle size, and the quad
/// size the triangulation is for.
io::ReadOptions mesh_read_options(const MeshOptions& options, const CommonOptions& common);

/// The mesher's options as the command line gives them.
QuadMeshOptions quad_mesh_options(const MeshOptions& options);

/// A quad mesh whose topology differs from the input's is broken output: throws
/// qm::Error(solver) (exit 1), naming where the parameterization failed.
void require_conforming(const MeshSummary& summary, const QuadMeshResult& result);

/// The warning lines on stderr (even with --quiet) for a mesh that is written but
/// flawed: dropped cells, cones that did not help, boundary points off the input's
/// boundary, inverted quads, quads far from the input (`diagonal`: the input's).
void warn_about_result(const MeshSummary& summary, const QuadMeshResult& result, double diagonal);

/// quadmesh mesh --each-component: every part of the input meshed on its own,
/// written to one output with a physical surface per part.
int run_mesh_each_component(const MeshOptions& options, const CommonOptions& common);

}  // namespace qm::tools
