// quadmesh quality MESH [--reference TRI] [--json]: the quality report of
// method.md section 10 for any triangle/quad mesh file.
#include "io/read_polygon_mesh.h"
#include "io/read_surface.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/topology/applicability.h"
#include "tools/common/exit_codes.h"
#include "tools/common/progress.h"
#include "tools/common/quality_json.h"
#include "tools/quadmesh/commands.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace qm::tools {

namespace {

/// "1.000" or "n/a" for a statistic that is not defined (NaN).
std::string value(double x, const char* spec = "{:.3f}") {
  return std::isnan(x) ? std::string("n/a") : fmt::format(fmt::runtime(spec), x);
}

/// "3: 4, 4: 120, 5: 4" (valence: vertices).
std::string histogram(const std::map<int, std::size_t>& counts) {
  if (counts.empty()) return "none";
  std::vector<std::string> items;
  for (const auto& [valence, count] : counts)
    items.push_back(fmt::format("{}: {}", valence, count));
  return fmt::format("{}", fmt::join(items, ", "));
}

/// "4 convex (0 wrong), 2 concave (1 wrong), 0 other": the reference's corners and
/// those not in max(1, round(angle / 90 deg)) quads.
std::string corners_text(const QuadQuality& q) {
  return fmt::format("{} convex of 60-120 deg ({} not in one quad), {} concave of 240-300 deg ({} not in three), "
                     "{} other ({} wrong)",
                     q.corners_convex, q.corners_convex_wrong, q.corners_concave, q.corners_concave_wrong,
                     q.corners_other, q.corners_other_wrong);
}

std::string quality_text(const QuadQuality& q, bool with_reference, double target_size) {
  std::string out;
  auto line = [&out](const char* key, const std::string& text) {
    out += fmt::format("{:<20}{}\n", key, text);
  };
  line("faces", fmt::format("{} quads, {} triangles, {} other; {} vertices", q.quads, q.triangles,
                            q.other_faces, q.vertices));
  line("inverted quads", fmt::format("{} (Verdict scaled Jacobian <= 0), {} turned over against their neighbours",
                                     q.inverted, q.flipped));
  line("scaled Jacobian", fmt::format("min {}, mean {}, p1 {} (Verdict)", value(q.min_scaled_jacobian),
                                      value(q.mean_scaled_jacobian), value(q.p01_scaled_jacobian)));
  line("angles", fmt::format("min {} deg, max {} deg (Verdict)", value(q.min_angle, "{:.1f}"),
                             value(q.max_angle, "{:.1f}")));
  line("warpage", fmt::format("min {}, mean {} (Verdict: 1 planar, <= 0 folded)", value(q.min_warpage),
                              value(q.mean_warpage)));
  line("aspect ratio", fmt::format("max {}, mean {} (Verdict)", value(q.aspect_ratio_max),
                                   value(q.aspect_ratio_mean)));
  line("skew, taper", fmt::format("max {}, {} (Verdict)", value(q.skew_max), value(q.taper_max)));
  if (q.triangles > 0)
    line("triangles", fmt::format("min scaled Jacobian {}, angles {}-{} deg, max aspect ratio {} (Verdict)",
                                  value(q.triangle_min_scaled_jacobian), value(q.triangle_min_angle, "{:.1f}"),
                                  value(q.triangle_max_angle, "{:.1f}"), value(q.triangle_aspect_ratio_max)));
  line("angle deviation", fmt::format("mean {} deg, p99 {} deg", value(q.angle_dev_mean, "{:.2f}"),
                                      value(q.angle_dev_p99, "{:.2f}")));
  line("irregular vertices",
       fmt::format("{} interior, {} boundary", q.irregular_interior, q.irregular_boundary));
  line("valence interior", histogram(q.valence_interior));
  line("valence boundary", histogram(q.valence_boundary));
  line("topology", fmt::format("chi {}, {} boundary loops{}{}", q.euler_characteristic,
                               q.boundary_loops, q.manifold ? "" : ", NOT manifold",
                               q.consistently_oriented ? "" : ", NOT consistently oriented"));
  if (target_size > 0)
    line("size", fmt::format("{} of the quads within [0.5, 2] x {:.4g}, largest {} x, smallest {} x",
                             std::isnan(q.size_band_share) ? std::string("n/a")
                                                           : fmt::format("{:.1f}%", 100 * q.size_band_share),
                             target_size, value(q.size_ratio_max, "{:.2f}"), value(q.size_ratio_min, "{:.2f}")));
  if (with_reference) {
    line("corners", corners_text(q));
    line("Hausdorff distance",
         fmt::format("{} of the diagonal (mesh to reference {}, reference to mesh {})",
                     value(q.hausdorff_rel, "{:.3g}"), value(q.hausdorff_forward_rel, "{:.3g}"),
                     value(q.hausdorff_backward_rel, "{:.3g}")));
  }
  return out;
}

/// The target size: --size, or P% of the bounding-box diagonal of the reference
/// (else of the mesh); 0 without --size.
double target_size(const QualityOptions& options, const PolygonMesh& mesh, const io::SurfaceFile* reference) {
  if (options.size > 0) return options.size;
  if (!(options.size_relative > 0)) return 0;
  if (reference) return options.size_relative * bounding_box_diagonal(reference->soup.points, reference->soup.triangles);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const std::vector<int>& face : mesh.faces)
    for (int v : face) {
      lo = lo.cwiseMin(mesh.points[static_cast<std::size_t>(v)]);
      hi = hi.cwiseMax(mesh.points[static_cast<std::size_t>(v)]);
    }
  return mesh.faces.empty() ? 0 : options.size_relative * (hi - lo).norm();
}

/// What `quadmesh info` refuses as invalid data (non-finite coordinates, a face
/// with a repeated vertex, duplicate faces) is refused here too, with info's
/// reason (exit 3): the figures of such a mesh mean nothing. Other defects
/// (non-manifold, several components) are measured and reported, not refused.
void require_valid_data(const std::string& path, const io::ReadOptions& read) {
  AnalyzedSurface surface = analyze_topology(io::read_surface(path, read).soup);
  const TopologyReport& r = surface.report;
  if (r.nonfinite_vertices.empty() && r.repeated_corner_faces.empty() && r.duplicate_faces.empty()) return;
  // assess_applicability names these first, in this order
  throw Error(ErrorCode::bad_input, fmt::format("{}: {}", path, assess_applicability(surface).reason));
}

}  // namespace

int run_quality(const QualityOptions& options, const CommonOptions& common) {
  const Progress progress(common.quiet || options.json);
  progress.stage(fmt::format("reading {}", options.input));
  io::ReadOptions read;
  read.cad_mesh_size = common.cad_mesh_size;
  require_valid_data(options.input, read);
  const PolygonMesh mesh = io::read_polygon_mesh(options.input);
  io::SurfaceFile reference;
  const bool with_reference = !options.reference.empty();
  if (with_reference) {
    progress.stage(fmt::format("reading the reference {}", options.reference));
    require_valid_data(options.reference, read);
    reference = io::read_surface(options.reference, read);
  }
  progress.stage("measuring quality");
  const double target = target_size(options, mesh, with_reference ? &reference : nullptr);
  const QuadQuality q = quad_quality(mesh, with_reference ? &reference.soup : nullptr, target);
  if (options.json)
    fmt::print("{}\n", quality_json(q).dump(2));
  else
    fmt::print("{}", quality_text(q, with_reference, target));
  return exit_ok;
}

}  // namespace qm::tools
