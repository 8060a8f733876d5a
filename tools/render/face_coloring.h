// What a mesh picture colours its faces by, and the colour scales: the per-face
// figures come from the quality module (Verdict's scaled Jacobian, the corner
// angle deviation of quad_shape_samples), the colours from a few fixed scales.
#pragma once

#include "libquadmesh/quality/quad_quality.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace qm::tools {

enum class FaceColoring {
  scaled_jacobian,  ///< `sj`: Verdict's scaled Jacobian of the quad (of the triangle, for triangles)
  angle_deviation,  ///< `angle`: the largest |corner angle - 90| of the quad, degrees
  size,             ///< `size`: mean edge length of the face / the reference size
  none,             ///< `none`: one colour, shading only
};

/// "sj", "angle", "size", "none" (the --color values), or nothing.
std::optional<FaceColoring> face_coloring_named(const std::string& name);
/// The --color values, for messages and help: "sj, angle, size, none".
std::string face_coloring_names();

/// Per face of `mesh` (in face order), the value its colour shows; NaN where the
/// coloring measures nothing (the angle deviation of a triangle, a face of more
/// than four corners, every face with FaceColoring::none). The scaled Jacobian of
/// a quad and its corner angles are quad_shape_samples's; of a triangle,
/// triangle_scaled_jacobian's. `size` (> 0) is the reference length of
/// FaceColoring::size.
std::vector<double> face_values(const PolygonMesh& mesh, FaceColoring coloring, double size);

/// An sRGB colour, each channel in [0, 1].
struct Rgb {
  double r = 0, g = 0, b = 0;
};

/// "#rrggbb".
std::string hex(const Rgb& c);

/// A colour scale: piecewise linear between `stops` (value, colour), clamped at
/// both ends; values at or below `special_below` (when set) take `special`.
struct ColorScale {
  std::string title;                        ///< what the colours mean, for the legend
  std::vector<std::pair<double, Rgb>> stops;  ///< increasing values
  bool log2 = false;                        ///< stops (and ticks) are log2 of the value
  std::vector<double> ticks;                ///< values labelled on the legend
  std::string tick_format = "{:g}";         ///< fmt spec of a tick label
  std::optional<double> special_below;      ///< e.g. 0 for the scaled Jacobian: inverted
  Rgb special;
  std::string special_label;                ///< "inverted (<= 0)"
};

/// The scale of a coloring (`size`: around 1, from 1/2 to 2 times the reference).
ColorScale color_scale(FaceColoring coloring);

/// The colour of `value` on `scale`; NaN takes kUnmeasured.
Rgb color_of(const ColorScale& scale, double value);

/// The colour of faces the coloring does not measure, and of every face with none.
inline constexpr Rgb kUnmeasured{0.80, 0.80, 0.80};
inline constexpr Rgb kPlain{0.62, 0.74, 0.86};

}  // namespace qm::tools
