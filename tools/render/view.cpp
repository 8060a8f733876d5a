#include "tools/render/view.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace qm::tools {

namespace {

/// Newell's vector area of every face with a non-zero one.
std::vector<Vec3> vector_areas(const PolygonMesh& mesh) {
  std::vector<Vec3> areas;
  areas.reserve(mesh.faces.size());
  for (const std::vector<int>& face : mesh.faces) {
    Vec3 sum = Vec3::Zero();
    for (std::size_t i = 0; i < face.size(); ++i)
      sum += mesh.points[static_cast<std::size_t>(face[i])].cross(
          mesh.points[static_cast<std::size_t>(face[(i + 1) % face.size()])]);
    if (sum.squaredNorm() > 0) areas.push_back(0.5 * sum);
  }
  return areas;
}

double front_area(const std::vector<Vec3>& areas, const Vec3& d) {
  double sum = 0;
  for (const Vec3& a : areas)
    sum += std::max(0.0, a.dot(d));
  return sum;
}

/// The fixed point of d <- normalize(sum of a_f with a_f . d > 0) from `d`.
Vec3 climb(const std::vector<Vec3>& areas, Vec3 d) {
  constexpr int kMaxSteps = 100;  // each step changes the set of front faces; it ends far sooner
  for (int step = 0; step < kMaxSteps; ++step) {
    Vec3 sum = Vec3::Zero();
    for (const Vec3& a : areas)
      if (a.dot(d) > 0) sum += a;
    if (sum.squaredNorm() == 0) return d;
    const Vec3 next = sum.normalized();
    if ((next - d).norm() < 1e-12) return next;
    d = next;
  }
  return d;
}

}  // namespace

Vec3 most_area_direction(const PolygonMesh& mesh) {
  const std::vector<Vec3> areas = vector_areas(mesh);
  if (areas.empty()) return Vec3::UnitZ();
  std::vector<Vec3> starts = {Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitY(),
                              -Vec3::UnitY(), Vec3::UnitX(), -Vec3::UnitX()};
  Vec3 total = Vec3::Zero();
  for (const Vec3& a : areas)
    total += a;
  if (total.squaredNorm() > 0) starts.insert(starts.begin(), total.normalized());
  Vec3 best = Vec3::UnitZ();
  double best_area = -1;
  for (const Vec3& start : starts) {
    const Vec3 d = climb(areas, start);
    const double area = front_area(areas, d);
    // a relative margin, so that rounding does not decide between equal views
    if (area > best_area * (1 + 1e-9)) {
      best_area = area;
      best = d;
    }
  }
  return best;
}

View view_toward(const Vec3& toward_viewer) {
  QM_ASSERT_MSG(toward_viewer.squaredNorm() > 0, "a view direction must not be zero");
  View view;
  view.toward_viewer = toward_viewer.normalized();
  // z up unless the view is within 25 degrees of it, then y, then x (at most one
  // axis can be that close to the view)
  constexpr double kSteepest = 0.906;  // cos 25 degrees
  Vec3 up = Vec3::UnitX();
  for (const Vec3& axis : {Vec3(Vec3::UnitZ()), Vec3(Vec3::UnitY())})
    if (std::abs(axis.dot(view.toward_viewer)) < kSteepest) {
      up = axis;
      break;
    }
  view.up = (up - up.dot(view.toward_viewer) * view.toward_viewer).normalized();
  view.right = view.up.cross(view.toward_viewer);
  return view;
}

Frame frame_fitting(const std::vector<Vec3>& points, const View& view, double width, double max_height) {
  QM_ASSERT_MSG(width > 0 && max_height > 0, "a picture needs a positive size");
  double u_min = std::numeric_limits<double>::infinity(), u_max = -u_min;
  double v_min = u_min, v_max = -u_min;
  for (const Vec3& p : points) {
    const double u = p.dot(view.right), v = p.dot(view.up);
    u_min = std::min(u_min, u);
    u_max = std::max(u_max, u);
    v_min = std::min(v_min, v);
    v_max = std::max(v_max, v);
  }
  const double extent = std::max(u_max - u_min, v_max - v_min);
  if (!(extent > 0) || !std::isfinite(extent))
    throw Error(ErrorCode::bad_input, "the surface has no extent to draw from this view");
  // Neither side may vanish: a mesh seen edge-on is drawn as a thin band.
  const double du = std::max(u_max - u_min, 1e-3 * extent), dv = std::max(v_max - v_min, 1e-3 * extent);
  constexpr double kMargin = 0.02;  // of the drawing, on each side
  const double inner = width * (1 - 2 * kMargin);
  Frame frame;
  frame.scale = std::min(inner / du, max_height * (1 - 2 * kMargin) / dv);
  frame.width = width;
  frame.height = std::min(max_height, dv * frame.scale / (1 - 2 * kMargin));
  frame.u_min = u_min - (width / frame.scale - du) / 2;  // centred across
  frame.v_max = v_max + (frame.height / frame.scale - dv) / 2;
  return frame;
}

Vec2 picture_point(const Vec3& p, const View& view, const Frame& frame) {
  return {frame.left + frame.scale * (p.dot(view.right) - frame.u_min),
          frame.top + frame.scale * (frame.v_max - p.dot(view.up))};
}

}  // namespace qm::tools
