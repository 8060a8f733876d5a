// The reports of `quadmesh compare`: report.json (one row per method, the same
// quality fields for all), report.md (a methods x metrics table with the best
// value per metric in bold, a verdict in words, the histogram pictures).
#pragma once

#include "libquadmesh/quality/quad_quality.h"
#include "tools/compare/child_process.h"
#include "tools/compare/methods.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace qm::tools {

/// One method's outcome: how its process ended and, when it wrote a readable mesh,
/// that mesh's quality against the shared reference.
struct MethodRun {
  Method method;
  ChildStatus status = ChildStatus::failed;  ///< ok only with a measured mesh
  double seconds = 0.0;                      ///< the child's wall-clock time
  std::string detail;                        ///< why it is not ok ("" when ok)
  std::optional<QuadQuality> quality;
  QuadShapeSamples samples;  ///< per-element values for the histograms (ok rows)
  std::string picture;       ///< its mesh as an SVG document (mesh_svg.h), "" without a mesh
};

struct ComparisonReport {
  std::string input;      ///< the input as given on the command line
  double size = 0.0;      ///< the target quad edge length every method got
  double diagonal = 0.0;  ///< bounding-box diagonal of the reference
  std::size_t reference_points = 0, reference_triangles = 0;
  int reference_euler_characteristic = 0;
  int reference_boundary_loops = 0;
  double timeout_seconds = 0.0;
  std::string gmsh_version;     ///< `gmsh --version`, or "" when it did not answer
  std::string gmsh_program;     ///< the Gmsh program the baselines ran (--gmsh)
  std::vector<MethodRun> runs;  ///< ours first
  std::vector<Method> skipped;  ///< methods this Gmsh cannot run (Method::skipped_because says why)
  Vec3 view = Vec3::UnitZ();    ///< the pictures' direction towards the viewer
};

/// The file of a method's picture in the output folder: "<name>.svg".
std::string picture_file(const Method& method);

/// The picture files report.md shows (in the output folder).
inline constexpr const char* kAngleHistogramFile = "angle-deviation.svg";
inline constexpr const char* kJacobianHistogramFile = "scaled-jacobian.svg";

/// {"input", "size", "diagonal", "reference", "timeout", "gmsh_version", "methods": [{"name",
/// "status", "seconds", "detail", "description", "mesh", "picture" (file or null), "quality":
/// {...} or null}], "skipped": [{"name", "reason", "description"}], "view": [x, y, z]}; the quality
/// object has quads, triangles, inverted, min_scaled_jacobian, mean_scaled_jacobian,
/// angle_dev_mean, angle_dev_p99, irregular_vertices
/// (= irregular_interior), boundary_loops, euler_characteristic, hausdorff_rel
/// (NaN as null), and edge_length_mean.
nlohmann::ordered_json report_json(const ComparisonReport& report);

/// report.md: title, input line, table (a skipped method is a `skipped` row), verdict, the
/// meshes' pictures side by side (three to a row; a method without a mesh says why
/// in its cell), the histograms, the methods.
std::string report_markdown(const ComparisonReport& report);

/// The verdict of report.md in a few sentences (also printed by the tool).
std::string report_verdict(const ComparisonReport& report);

/// The two histogram pictures (angle deviation per quad corner, scaled Jacobian
/// per quad) of every method, as SVG documents.
std::string angle_histogram_svg(const ComparisonReport& report);
std::string jacobian_histogram_svg(const ComparisonReport& report);

}  // namespace qm::tools
