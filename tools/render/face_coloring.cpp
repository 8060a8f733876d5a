#include "tools/render/face_coloring.h"

#include "libquadmesh/core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace qm::tools {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Rgb rgb(int hex_value) {
  return {((hex_value >> 16) & 0xff) / 255.0, ((hex_value >> 8) & 0xff) / 255.0, (hex_value & 0xff) / 255.0};
}

/// ColorBrewer's RdYlBu (5 classes): red for the worst, blue for the best.
std::vector<std::pair<double, Rgb>> red_to_blue(double worst, double best) {
  const int colors[] = {0xd7191c, 0xfdae61, 0xffffbf, 0xabd9e9, 0x2c7bb6};
  std::vector<std::pair<double, Rgb>> stops;
  for (int i = 0; i < 5; ++i)
    stops.emplace_back(worst + (best - worst) * i / 4.0, rgb(colors[i]));
  if (worst > best) std::reverse(stops.begin(), stops.end());
  return stops;
}

}  // namespace

std::optional<FaceColoring> face_coloring_named(const std::string& name) {
  if (name == "sj") return FaceColoring::scaled_jacobian;
  if (name == "angle") return FaceColoring::angle_deviation;
  if (name == "size") return FaceColoring::size;
  if (name == "none") return FaceColoring::none;
  return std::nullopt;
}

std::string face_coloring_names() { return "sj, angle, size, none"; }

std::vector<double> face_values(const PolygonMesh& mesh, FaceColoring coloring, double size) {
  std::vector<double> values(mesh.faces.size(), kNaN);
  if (coloring == FaceColoring::none) return values;
  if (coloring == FaceColoring::size) {
    QM_ASSERT_MSG(size > 0, "the size coloring needs a positive reference size");
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const std::vector<int>& face = mesh.faces[f];
      double sum = 0;
      for (std::size_t i = 0; i < face.size(); ++i)
        sum += (mesh.points[static_cast<std::size_t>(face[(i + 1) % face.size()])] -
                mesh.points[static_cast<std::size_t>(face[i])])
                   .norm();
      values[f] = sum / static_cast<double>(face.size()) / size;
    }
    return values;
  }
  // quad_shape_samples lists the quads in face order, four corners each
  const QuadShapeSamples samples = quad_shape_samples(mesh);
  std::size_t quad = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    const auto point = [&](std::size_t k) -> const Vec3& { return mesh.points[static_cast<std::size_t>(face[k])]; };
    if (face.size() == 4) {
      if (coloring == FaceColoring::scaled_jacobian) {
        values[f] = samples.scaled_jacobian[quad];
      } else {
        const auto first = samples.angle_deviation_deg.begin() + static_cast<std::ptrdiff_t>(4 * quad);
        values[f] = *std::max_element(first, first + 4);
      }
      ++quad;
    } else if (face.size() == 3 && coloring == FaceColoring::scaled_jacobian) {
      values[f] = triangle_scaled_jacobian({point(0), point(1), point(2)});
    }
  }
  return values;
}

std::string hex(const Rgb& c) {
  const auto channel = [](double x) { return static_cast<int>(std::lround(std::clamp(x, 0.0, 1.0) * 255)); };
  return fmt::format("#{:02x}{:02x}{:02x}", channel(c.r), channel(c.g), channel(c.b));
}

ColorScale color_scale(FaceColoring coloring) {
  ColorScale scale;
  switch (coloring) {
    case FaceColoring::scaled_jacobian:
      scale.title = "scaled Jacobian (Verdict)";
      scale.stops = red_to_blue(0.0, 1.0);
      scale.ticks = {0.0, 0.25, 0.5, 0.75, 1.0};
      scale.special_below = 0.0;
      scale.special = rgb(0x40004b);
      scale.special_label = "inverted (<= 0)";
      break;
    case FaceColoring::angle_deviation:
      scale.title = "max |corner angle - 90| (deg)";
      scale.stops = red_to_blue(45.0, 0.0);
      scale.ticks = {0.0, 10.0, 20.0, 30.0, 45.0};
      break;
    case FaceColoring::size: {
      scale.title = "mean edge / size";
      const int colors[] = {0x5e3c99, 0xb2abd2, 0xf7f7f7, 0xfdb863, 0xe66101};  // ColorBrewer PuOr
      for (int i = 0; i < 5; ++i)
        scale.stops.emplace_back(-1.0 + 0.5 * i, rgb(colors[i]));
      scale.log2 = true;
      scale.ticks = {0.5, 0.71, 1.0, 1.41, 2.0};
      break;
    }
    case FaceColoring::none:
      scale.title = "";
      break;
  }
  return scale;
}

Rgb color_of(const ColorScale& scale, double value) {
  if (std::isnan(value) || scale.stops.empty()) return scale.stops.empty() ? kPlain : kUnmeasured;
  if (scale.special_below && value <= *scale.special_below) return scale.special;
  const double x = scale.log2 ? std::log2(std::max(value, 1e-300)) : value;
  if (x <= scale.stops.front().first) return scale.stops.front().second;
  if (x >= scale.stops.back().first) return scale.stops.back().second;
  for (std::size_t i = 1; i < scale.stops.size(); ++i) {
    const auto& [x1, c1] = scale.stops[i];
    if (x > x1) continue;
    const auto& [x0, c0] = scale.stops[i - 1];
    const double t = (x - x0) / (x1 - x0);
    return {c0.r + t * (c1.r - c0.r), c0.g + t * (c1.g - c0.g), c0.b + t * (c1.b - c0.b)};
  }
  return scale.stops.back().second;
}

}  // namespace qm::tools
