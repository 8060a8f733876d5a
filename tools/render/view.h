// The view of a mesh picture: the direction the surface is seen from (the one
// that shows the most of it, or the user's), and how its orthographic
// projection fits the picture.
#pragma once

#include "libquadmesh/quality/quad_quality.h"

#include <Eigen/Core>

#include <vector>

namespace qm::tools {

using Vec2 = Eigen::Vector2d;

/// An orthographic view. `toward_viewer` is the unit direction from the surface to
/// the eye: a face whose normal (CCW corners) has a positive component along it
/// shows its front. `right` and `up` span the picture plane, right x up =
/// toward_viewer (a right-handed frame, so a face CCW in space is CCW on screen
/// when it faces the viewer).
struct View {
  Vec3 toward_viewer = Vec3::UnitZ();
  Vec3 right = Vec3::UnitX();
  Vec3 up = Vec3::UnitY();
};

/// The direction that shows the most area: the unit d maximizing the front-facing
/// projected area sum_f max(0, a_f . d), a_f the vector area of face f (Newell).
/// Since that sum is the largest (sum over S of a_f) . d over the sets S of faces,
/// the fixed point d <- normalize(sum of a_f with a_f . d > 0) never decreases it;
/// it is run from the six axis directions and the normalized sum of all a_f, and
/// the best end kept (the first of equal ones). A flat mesh gets its normal.
/// Returns +z when no face has an area.
Vec3 most_area_direction(const PolygonMesh& mesh);

/// The view from `toward_viewer` (non-zero; normalized here): up is the world z
/// axis made orthogonal to it, or y when the view is within 25 degrees of z, or x
/// when it is within 25 degrees of y too (CAD's z up; a plate in the xy plane
/// seen from above has y up); right = up x toward_viewer.
View view_toward(const Vec3& toward_viewer);

/// Where the projection goes: picture x = left + scale (p . right - u_min),
/// y = top + scale (v_max - p . up) (SVG's y points down). `width` and `height`
/// are the drawing's extent in picture units (px).
struct Frame {
  double u_min = 0, v_max = 0;
  double scale = 1;
  double left = 0, top = 0;
  double width = 0, height = 0;
};

/// The frame that shows every one of `points` in a drawing `width` px wide with a
/// margin of 2% on each side; the height follows the projection's aspect ratio,
/// at most `max_height` (then the drawing is narrower and centred). Throws
/// qm::Error(bad_input) when the projection has no extent (all points on one
/// line along the view).
Frame frame_fitting(const std::vector<Vec3>& points, const View& view, double width, double max_height);

/// The picture point of `p`.
Vec2 picture_point(const Vec3& p, const View& view, const Frame& frame);

/// Depth along the view: larger is nearer the viewer.
inline double view_depth(const Vec3& p, const View& view) { return p.dot(view.toward_viewer); }

}  // namespace qm::tools
