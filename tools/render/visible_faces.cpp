#include "tools/render/visible_faces.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace qm::tools {

namespace {

/// A depth buffer with the face nearest at every sample.
class DepthBuffer {
 public:
  DepthBuffer(double width, double height, int per_pixel)
      : per_pixel_(per_pixel),
        columns_(static_cast<int>(std::ceil(width * per_pixel))),
        rows_(static_cast<int>(std::ceil(height * per_pixel))),
        depth_(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_),
               -std::numeric_limits<double>::infinity()),
        face_(depth_.size(), -1) {}

  /// Rasterizes the triangle (a, b, c) (picture coordinates relative to the
  /// drawing's corner, with their depths) at the sample centres it covers.
  void draw(const Vec2& a, const Vec2& b, const Vec2& c, double za, double zb, double zc, int face) {
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (area == 0 || !std::isfinite(area)) return;  // seen edge-on
    const double s = per_pixel_;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}) * s)));
    const int x1 = std::min(columns_ - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}) * s)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}) * s)));
    const int y1 = std::min(rows_ - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}) * s)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec2 p((x + 0.5) / s, (y + 0.5) / s);
        // barycentric coordinates; the sample is inside (or on an edge) when all are >= 0
        const double wa = ((b - p).x() * (c - p).y() - (b - p).y() * (c - p).x()) / area;
        const double wb = ((c - p).x() * (a - p).y() - (c - p).y() * (a - p).x()) / area;
        const double wc = 1 - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        const double z = wa * za + wb * zb + wc * zc;
        const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(columns_) +
                               static_cast<std::size_t>(x);
        if (z > depth_[at]) {
          depth_[at] = z;
          face_[at] = face;
        }
      }
  }

  /// Per face of `count`, whether it is the nearest at some sample.
  std::vector<char> shown(std::size_t count) const {
    std::vector<char> out(count, 0);
    for (int f : face_)
      if (f >= 0) out[static_cast<std::size_t>(f)] = 1;
    return out;
  }

 private:
  int per_pixel_, columns_, rows_;
  std::vector<double> depth_;
  std::vector<int> face_;
};

Vec3 unit_normal(const PolygonMesh& mesh, const std::vector<int>& face) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < face.size(); ++i)
    sum += mesh.points[static_cast<std::size_t>(face[i])].cross(
        mesh.points[static_cast<std::size_t>(face[(i + 1) % face.size()])]);
  return sum.squaredNorm() > 0 ? Vec3(sum.normalized()) : Vec3(Vec3::Zero());
}

}  // namespace

std::vector<DrawnFace> visible_faces(const PolygonMesh& mesh, const View& view, const Frame& frame,
                                     int samples_per_pixel) {
  QM_ASSERT_MSG(samples_per_pixel >= 1, "at least one sample per pixel");
  std::vector<DrawnFace> all(mesh.faces.size());
  DepthBuffer buffer(frame.width, frame.height, samples_per_pixel);
  const Vec2 corner(frame.left, frame.top);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    DrawnFace& drawn = all[f];
    drawn.face = static_cast<int>(f);
    std::vector<double> depths;
    Vec3 centroid = Vec3::Zero();
    for (int v : face) {
      const Vec3& p = mesh.points[static_cast<std::size_t>(v)];
      drawn.corners.push_back(picture_point(p, view, frame));
      depths.push_back(view_depth(p, view));
      centroid += p;
    }
    drawn.depth = view_depth(centroid / static_cast<double>(face.size()), view);
    drawn.facing = unit_normal(mesh, face).dot(view.toward_viewer);
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      buffer.draw(drawn.corners[0] - corner, drawn.corners[i] - corner, drawn.corners[i + 1] - corner, depths[0],
                  depths[i], depths[i + 1], static_cast<int>(f));
  }
  const std::vector<char> shown = buffer.shown(mesh.faces.size());
  std::vector<DrawnFace> out;
  for (std::size_t f = 0; f < all.size(); ++f)
    if (shown[f]) out.push_back(std::move(all[f]));
  std::stable_sort(out.begin(), out.end(),
                   [](const DrawnFace& a, const DrawnFace& b) { return a.depth < b.depth; });
  return out;
}

}  // namespace qm::tools
