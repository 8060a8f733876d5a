#include "tools/common/quality_json.h"

#include <cmath>
#include <string>

namespace qm::tools {

namespace {

using Json = nlohmann::ordered_json;

/// nlohmann writes non-finite numbers as null already; this makes it explicit.
Json number(double x) {
  return std::isfinite(x) ? Json(x) : Json(nullptr);
}

Json histogram(const std::map<int, std::size_t>& counts) {
  Json j = Json::object();
  for (const auto& [valence, count] : counts)
    j[std::to_string(valence)] = count;
  return j;
}

}  // namespace

Json quality_json(const QuadQuality& q) {
  Json j;
  j["vertices"] = q.vertices;
  j["quads"] = q.quads;
  j["triangles"] = q.triangles;
  j["other_faces"] = q.other_faces;
  j["inverted"] = q.inverted;
  j["flipped"] = q.flipped;
  j["min_scaled_jacobian"] = number(q.min_scaled_jacobian);
  j["mean_scaled_jacobian"] = number(q.mean_scaled_jacobian);
  j["p01_scaled_jacobian"] = number(q.p01_scaled_jacobian);
  j["min_angle"] = number(q.min_angle);
  j["max_angle"] = number(q.max_angle);
  j["min_warpage"] = number(q.min_warpage);
  j["mean_warpage"] = number(q.mean_warpage);
  j["aspect_ratio_mean"] = number(q.aspect_ratio_mean);
  j["aspect_ratio_max"] = number(q.aspect_ratio_max);
  j["skew_mean"] = number(q.skew_mean);
  j["skew_max"] = number(q.skew_max);
  j["taper_mean"] = number(q.taper_mean);
  j["taper_max"] = number(q.taper_max);
  j["min_normal_consistency"] = number(q.min_normal_consistency);
  j["triangle_min_scaled_jacobian"] = number(q.triangle_min_scaled_jacobian);
  j["triangle_min_angle"] = number(q.triangle_min_angle);
  j["triangle_max_angle"] = number(q.triangle_max_angle);
  j["triangle_aspect_ratio_max"] = number(q.triangle_aspect_ratio_max);
  j["angle_dev_mean"] = number(q.angle_dev_mean);
  j["angle_dev_rms"] = number(q.angle_dev_rms);
  j["angle_dev_p99"] = number(q.angle_dev_p99);
  j["angle_dev_max"] = number(q.angle_dev_max);
  j["valence_interior"] = histogram(q.valence_interior);
  j["valence_boundary"] = histogram(q.valence_boundary);
  j["irregular_interior"] = q.irregular_interior;
  j["irregular_boundary"] = q.irregular_boundary;
  j["euler_characteristic"] = q.euler_characteristic;
  j["boundary_loops"] = q.boundary_loops;
  j["manifold"] = q.manifold;
  j["consistently_oriented"] = q.consistently_oriented;
  j["edge_length_min"] = number(q.edge_length_min);
  j["edge_length_mean"] = number(q.edge_length_mean);
  j["edge_length_max"] = number(q.edge_length_max);
  j["boundary_alignment_mean"] = number(q.boundary_alignment_mean);
  j["boundary_alignment_max"] = number(q.boundary_alignment_max);
  j["size_band_share"] = number(q.size_band_share);
  j["size_ratio_max"] = number(q.size_ratio_max);
  j["size_ratio_min"] = number(q.size_ratio_min);
  j["corners"] = {{"convex", q.corners_convex},   {"convex_wrong", q.corners_convex_wrong},
                  {"concave", q.corners_concave}, {"concave_wrong", q.corners_concave_wrong},
                  {"other", q.corners_other},     {"other_wrong", q.corners_other_wrong}};
  j["hausdorff_rel"] = number(q.hausdorff_rel);
  j["hausdorff_forward_rel"] = number(q.hausdorff_forward_rel);
  j["hausdorff_backward_rel"] = number(q.hausdorff_backward_rel);
  if (!std::isnan(q.hausdorff_rel)) j["hausdorff_at"] = {q.hausdorff_at.x(), q.hausdorff_at.y(), q.hausdorff_at.z()};
  return j;
}

}  // namespace qm::tools
