// Quality of a quad (or quad-dominant) mesh: what every result reports
// (method.md section 10). Shape per quad and per triangle by Verdict's definitions
// (verdict.h: scaled Jacobian, angles, warpage, aspect ratio, skew, taper), the
// normal consistency that Verdict cannot see (a quad turned over against its
// neighbours), corner angle deviations, valences against the regular grid,
// topology checks, edge lengths, alignment with the boundary and the two-sided
// Hausdorff distance to the input.
//
// Conventions: faces are listed counterclockwise seen from the front, so the
// normal consistency of a well-shaped quad is positive with respect to the vertex
// normals; angles are in degrees; statistics over an empty set are NaN.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/quality/verdict.h"

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace qm {

/// A polygon mesh as read from a file: faces of 3, 4 (or more) point indices,
/// counterclockwise seen from the front.
struct PolygonMesh {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
};

/// Everything method.md section 10 asks of a quad mesh. NaN: not defined for this
/// mesh (no quads, no boundary, no reference).
struct QuadQuality {
  // counts
  std::size_t vertices = 0;     ///< points referenced by a face
  std::size_t quads = 0;        ///< faces with 4 corners
  std::size_t triangles = 0;    ///< faces with 3 corners
  std::size_t other_faces = 0;  ///< faces with more than 4 corners
  std::size_t inverted = 0;     ///< quads whose Verdict scaled Jacobian is <= 0
  std::size_t flipped = 0;      ///< quads turned over against their neighbours (normal
                                ///< consistency <= 0), which Verdict cannot see

  // Verdict figures of the quads (verdict.h): worst, mean and percentiles over the quads
  double min_scaled_jacobian = 0;   ///< smallest Verdict scaled Jacobian (1 = rectangle, <= 0 = inverted)
  double mean_scaled_jacobian = 0;  ///< mean over the quads
  double p01_scaled_jacobian = 0;   ///< 1st percentile over the quads
  double min_angle = 0;             ///< smallest Verdict minimum angle, degrees
  double max_angle = 0;             ///< largest Verdict maximum angle, degrees
  double min_warpage = 0;           ///< smallest Verdict warpage (1 = planar, <= 0 = folded)
  double mean_warpage = 0;          ///< mean Verdict warpage
  double aspect_ratio_mean = 0;     ///< mean Verdict aspect ratio (1 = square)
  double aspect_ratio_max = 0;      ///< largest Verdict aspect ratio
  double skew_mean = 0;             ///< mean Verdict skew (0 = orthogonal axes)
  double skew_max = 0;              ///< largest Verdict skew
  double taper_mean = 0;            ///< mean Verdict taper (0 = parallelogram)
  double taper_max = 0;             ///< largest Verdict taper

  /// Smallest normal consistency over the quads: the corner scaled Jacobian
  /// against the mesh's vertex normals (corner_scaled_jacobian), <= 0 for a quad
  /// turned over against its neighbours. Not a Verdict figure.
  double min_normal_consistency = 0;
  /// Smallest sound_scaled_jacobian over the quads: the Verdict scaled Jacobian
  /// capped by the normal consistency, quad by quad (<= both minima above). What the
  /// pipeline's acceptance criteria hold the quads to (pipeline/acceptance_criteria.h).
  double min_sound_scaled_jacobian = 0;

  // Verdict figures of the triangles left in the mesh (NaN without triangles)
  double triangle_min_scaled_jacobian = 0;  ///< smallest (no sign in 3D: [0, 1])
  double triangle_min_angle = 0;            ///< smallest angle, degrees
  double triangle_max_angle = 0;            ///< largest angle, degrees
  double triangle_aspect_ratio_max = 0;     ///< largest aspect ratio (1 = equilateral)

  // deviation |angle - 90| of the quad corner angles, degrees (not a Verdict figure:
  // what method.md section 10 asks of a quad mesh)
  double angle_dev_mean = 0;  ///< mean over all quad corners
  double angle_dev_rms = 0;   ///< root mean square over all quad corners
  double angle_dev_p99 = 0;   ///< 99th percentile over all quad corners
  double angle_dev_max = 0;   ///< largest over all quad corners

  // valences
  std::map<int, std::size_t> valence_interior;  ///< edges at an interior vertex -> vertex count
  std::map<int, std::size_t> valence_boundary;  ///< faces at a boundary vertex -> vertex count
  std::size_t irregular_interior = 0;           ///< interior vertices with valence != 4
  std::size_t irregular_boundary = 0;           ///< boundary vertices whose face count is not
                                                ///< max(1, round(corner angle sum / 90 deg))

  // topology
  int euler_characteristic = 0;       ///< V - E + F over the referenced vertices
  int boundary_loops = 0;             ///< closed cycles of boundary edges (one face each)
  bool manifold = true;               ///< edges have <= 2 faces, each vertex's faces form one fan
  bool consistently_oriented = true;  ///< every interior edge used once in each direction

  // edge lengths (every distinct edge of every face)
  double edge_length_min = 0;   ///< shortest edge
  double edge_length_mean = 0;  ///< mean edge length
  double edge_length_max = 0;   ///< longest edge

  // alignment of the interior edges that leave a boundary vertex, degrees
  double boundary_alignment_mean = 0;  ///< mean |angle(edge, boundary tangent) - 90|
  double boundary_alignment_max = 0;   ///< largest |angle(edge, boundary tangent) - 90|

  // quad size (mean edge length of the quad) against the target size (size_band.h;
  // NaN without a target)
  double size_band_share = 0;  ///< share of the quads within [0.5, 2] x the target
  double size_ratio_max = 0;   ///< largest quad size / target
  double size_ratio_min = 0;   ///< smallest quad size / target

  // the reference's corners and the quads at each (corner_quads.h; 0 without a
  // reference)
  std::size_t corners_convex = 0;         ///< corners of 60-120 degrees
  std::size_t corners_convex_wrong = 0;   ///< of those, not in exactly one quad
  std::size_t corners_concave = 0;        ///< corners of 240-300 degrees
  std::size_t corners_concave_wrong = 0;  ///< of those, not in exactly three quads
  std::size_t corners_other = 0;          ///< other corners (more than 45 degrees from straight)
  std::size_t corners_other_wrong = 0;    ///< of those, not in max(1, round(angle / 90 deg)) quads

  // two-sided Hausdorff distance to the reference, relative to its bounding-box
  // diagonal (NaN without a reference)
  double hausdorff_rel = 0;           ///< max(forward, backward) / diagonal
  double hausdorff_forward_rel = 0;   ///< farthest mesh sample from the reference / diagonal
  double hausdorff_backward_rel = 0;  ///< farthest reference sample from the mesh / diagonal
  Vec3 hausdorff_at = Vec3::Zero();   ///< the sample (of the mesh or the reference) at that distance
};

/// The reference's corners, all three kinds, and those of them in the wrong number of quads.
inline std::size_t corners_total(const QuadQuality& q) {
  return q.corners_convex + q.corners_concave + q.corners_other;
}
inline std::size_t corners_wrong(const QuadQuality& q) {
  return q.corners_convex_wrong + q.corners_concave_wrong + q.corners_other_wrong;
}

/// The per-element values behind QuadQuality's shape statistics, for histograms:
/// one entry per quad (in face order) or per quad corner. Triangles and larger
/// faces are skipped.
struct QuadShapeSamples {
  std::vector<QuadVerdict> verdict;          ///< per quad: its Verdict figures
  std::vector<double> scaled_jacobian;       ///< per quad: Verdict scaled Jacobian (<= 0: inverted)
  std::vector<double> normal_consistency;    ///< per quad: min corner scaled Jacobian against the vertex normals
  std::vector<double> sound_scaled_jacobian; ///< per quad: sound_scaled_jacobian (the two above combined)
  std::vector<double> angle_deviation_deg;   ///< per quad corner: |angle - 90|, degrees
};

/// The Verdict figures, normal consistencies and corner angle deviations of the
/// quads of `mesh`, exactly as quad_quality measures them.
QuadShapeSamples quad_shape_samples(const PolygonMesh& mesh);

/// What the pipeline holds every quad to: its Verdict scaled Jacobian, capped by
/// its normal consistency (the smallest corner_scaled_jacobian against
/// `normals`, the unit vertex normals at its corners), so that neither a warped
/// quad nor one turned over against its neighbours passes. <= the Verdict figure.
double sound_scaled_jacobian(const QuadPoints& corners, const std::array<Vec3, 4>& normals);

/// sound_scaled_jacobian of every quad of `mesh` (in face order; triangles and
/// larger faces skipped), with the mesh's own vertex normals.
std::vector<double> sound_scaled_jacobians(const PolygonMesh& mesh);

/// Measures `mesh` (faces CCW seen from the front; degenerate faces are measured,
/// not rejected) and, when `reference` is not null, its two-sided Hausdorff
/// distance to that triangulated surface (hausdorff.h; quads split along 0-2).
/// With `target_size` > 0 the quad sizes are set against it (size_band.h), and
/// with a reference its corners are checked (corner_quads.h), seen at the target's
/// scale when there is one, else at the mesh's mean edge.
/// Every field is documented in QuadQuality.
QuadQuality quad_quality(const PolygonMesh& mesh, const TriangleSoup* reference, double target_size = 0);

/// The area-weighted vertex normals of a polygon mesh: the normalized sum of the
/// vector areas of the faces around each point (zero for isolated points or where
/// the sum vanishes).
std::vector<Vec3> vertex_normals(const PolygonMesh& mesh);

/// Scaled Jacobian of the corner at `p` with edges to `next` and `prev` (the
/// following and the preceding corner of a CCW face), with respect to the unit
/// normal `n`: ((next - p) x (prev - p)) . n / (|next - p| |prev - p|), in [-1, 1];
/// 1 for a right angle, <= 0 for a corner folded over. 0 if an edge has zero length.
double corner_scaled_jacobian(const Vec3& prev, const Vec3& p, const Vec3& next, const Vec3& n);

/// The angle at `p` between the edges to `prev` and `next`, in degrees in [0, 180]
/// (0 if an edge has zero length).
double corner_angle_deg(const Vec3& prev, const Vec3& p, const Vec3& next);

}  // namespace qm
