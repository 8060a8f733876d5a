// What `quadmesh mesh` writes and prints: the output mesh with its physical
// groups, the one-screen summary and the JSON report (--report).
#pragma once

#include "io/write_mesh.h"
#include "libquadmesh/extract/quadratic_quads.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "libquadmesh/quality/curved_jacobian.h"
#include "libquadmesh/quality/quad_quality.h"
#include "tools/common/input_surface.h"
#include "tools/quadmesh/commands.h"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <set>

namespace qm::tools {

struct MeshSummary {
  std::string input;
  QuadQuality quality;
  int expected_irregular_interior = 0;  ///< interior zeros (one vertex each)
  int expected_irregular_boundary = 0;  ///< boundary zeros
  int input_euler_characteristic = 0;
  int input_boundary_loops = 0;
  double seconds = 0;
  std::optional<CurvedJacobians> curved;  ///< --order 2: of the quadratic quads
  int nodes_per_quad = 4;
  nlohmann::ordered_json report;  ///< everything, for --report
};

/// Which CAD curves a point of S lies on (the curves of the input boundary edges
/// through it): a point on an edge of a curve, or a vertex of one or more.
struct CurveLookup {
  std::map<std::pair<int, int>, int> curve_of_edge;  ///< (smaller, larger end) -> curve tag
  std::multimap<int, int> curves_of_vertex;
  std::set<int> at(const SurfaceLocation& location) const;
};
CurveLookup curve_lookup(const CadCurves& cad);

/// The quad mesh with one physical curve per boundary loop ("boundary_k", or the
/// CAD physical group's name where the input had one) and the surface group; with
/// `quadratic` (built from result.quads), its points and 8- or 9-node quads, and
/// the node of each boundary edge in the line groups.
io::OutputMesh output_mesh(const QuadMeshResult& result, const QuadraticQuads* quadratic = nullptr);

/// The quadratic quads of --order 2 (extract/quadratic_quads.h); for CAD input
/// (`cad_path` not empty) every boundary node moved onto its CAD curve (io/
/// cad_curve_points.h): an edge node onto the curve both ends of its edge lie on, a
/// corner on one curve onto it (from the triangulation's chord, by its sagitta).
/// `input`: the surface as read; the nodes go onto it when the quads were meshed
/// on a coarser working triangulation (QuadMeshResult::coarsened_from), else onto
/// result.surface.
QuadraticQuads quadratic_output(const QuadMeshResult& result, bool complete, const std::string& cad_path,
                                const TriangleSoup& input);

MeshSummary summarize(const InputSurface& in, const QuadMeshResult& result, const MeshOptions& options,
                      double seconds, const QuadraticQuads* quadratic = nullptr);

void print_summary(const MeshSummary& summary);
/// Writes the JSON report to `path` as it is (the caller makes it atomic, with
/// the mesh); throws qm::Error(bad_input) if it cannot.
void write_report(const std::string& path, const MeshSummary& summary);

}  // namespace qm::tools
