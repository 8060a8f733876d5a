// What `quadmesh mesh` writes and prints: the output mesh with its physical
// groups, the one-screen summary and the JSON report (--report).
#pragma once

#include "io/write_mesh.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "libquadmesh/quality/quad_quality.h"
#include "tools/common/input_surface.h"
#include "tools/quadmesh/commands.h"

#include <nlohmann/json.hpp>

namespace qm::tools {

struct MeshSummary {
  std::string input;
  QuadQuality quality;
  int expected_irregular_interior = 0;  ///< interior zeros (one vertex each)
  int expected_irregular_boundary = 0;  ///< boundary zeros
  int input_euler_characteristic = 0;
  int input_boundary_loops = 0;
  double seconds = 0;
  nlohmann::ordered_json report;  ///< everything, for --report
};

/// The quad mesh with one physical curve per boundary loop ("boundary_k", or the
/// CAD physical group's name where the input had one) and the surface group.
io::OutputMesh output_mesh(const QuadMeshResult& result);

MeshSummary summarize(const InputSurface& in, const QuadMeshResult& result, const MeshOptions& options,
                      double seconds);

void print_summary(const MeshSummary& summary);
/// Writes the JSON report to `path` as it is (the caller makes it atomic, with
/// the mesh); throws qm::Error(bad_input) if it cannot.
void write_report(const std::string& path, const MeshSummary& summary);

}  // namespace qm::tools
