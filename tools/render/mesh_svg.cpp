#include "tools/render/mesh_svg.h"

#include "tools/common/xml_text.h"
#include "tools/render/irregular_vertices.h"
#include "tools/render/visible_faces.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace qm::tools {

namespace {

// Layout, in px: the title above the drawing, the legend on its right, the caption below.
constexpr double kPad = 10;
constexpr double kTitleHeight = 26;
constexpr double kLegendWidth = 190;
constexpr double kCaptionLine = 16;
/// Edges shorter than this on screen (median, px) are not drawn.
constexpr double kMinEdgePx = 2.5;

/// How much of a face's colour its light keeps: a headlight along the view.
Rgb shaded(const Rgb& base, double facing) {
  const double light = 0.55 + 0.45 * std::abs(facing);
  Rgb c{base.r * light, base.g * light, base.b * light};
  if (facing < 0) {  // its back shows: greyed, as Gmsh and ParaView tell the sides apart
    constexpr double kGrey = 0.55, kMix = 0.45;
    c = {c.r + kMix * (kGrey - c.r), c.g + kMix * (kGrey - c.g), c.b + kMix * (kGrey - c.b)};
  }
  return c;
}

/// The fill of a singular vertex's circle, by valence.
const char* valence_fill(int valence) {
  if (valence <= 2) return "#00a000";
  if (valence == 3) return "#000000";
  if (valence == 5) return "#ffffff";
  return "#ff00ff";
}

std::string valence_name(int valence) {
  return valence <= 2 ? "<= 2" : valence >= 6 ? ">= 6" : std::to_string(valence);
}

/// The valence classes the legend shows (valence_name), ordered as valence_fill's.
int valence_class(int valence) { return valence <= 2 ? 2 : valence >= 6 ? 6 : valence; }

/// The median length of the drawn edges in px: sets the stroke and marker sizes.
double median_edge_px(const std::vector<DrawnFace>& faces) {
  std::vector<double> lengths;
  for (const DrawnFace& f : faces)
    for (std::size_t i = 0; i < f.corners.size(); ++i)
      lengths.push_back((f.corners[(i + 1) % f.corners.size()] - f.corners[i]).norm());
  if (lengths.empty()) return 10;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2),
                   lengths.end());
  return lengths[lengths.size() / 2];
}

std::string polygon(const DrawnFace& face, const Rgb& fill) {
  std::string points;
  for (const Vec2& p : face.corners)
    points += fmt::format("{}{:.1f},{:.1f}", points.empty() ? "" : " ", p.x(), p.y());
  return fmt::format("<polygon points=\"{}\" fill=\"{}\"/>\n", points, hex(fill));
}

/// The colour bar (and the swatches of what it does not cover) at (x, y).
std::string color_legend(const ColorScale& scale, FaceColoring coloring, bool has_unmeasured, double x,
                         double& y) {
  std::string svg;
  if (scale.stops.empty()) return svg;
  const double bar_w = 16, bar_h = 150;
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-weight=\"bold\">{}</text>\n", x, y,
                     xml_escaped(scale.title));
  y += 10;
  const double lo = scale.stops.front().first, hi = scale.stops.back().first;
  // vertical, best (the last stop of a quality scale) on top
  svg += "<defs><linearGradient id=\"scale\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (const auto& [value, color] : scale.stops)
    svg += fmt::format("<stop offset=\"{:.3f}\" stop-color=\"{}\"/>", (value - lo) / (hi - lo), hex(color));
  svg += "</linearGradient></defs>\n";
  svg += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{}\" height=\"{}\" fill=\"url(#scale)\" stroke=\"#444\"/>\n",
                     x, y, bar_w, bar_h);
  for (double tick : scale.ticks) {
    const double t = ((scale.log2 ? std::log2(tick) : tick) - lo) / (hi - lo);
    const double ty = y + bar_h * (1 - t);
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#444\"/>"
        "<text x=\"{3:.1f}\" y=\"{4:.1f}\">{5}</text>\n",
        x + bar_w, ty, x + bar_w + 4, x + bar_w + 7, ty + 4, fmt::format(fmt::runtime(scale.tick_format), tick));
  }
  y += bar_h + 20;
  const auto swatch = [&](const Rgb& color, const std::string& label) {
    svg += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{}\" height=\"12\" fill=\"{}\" stroke=\"#444\"/>"
        "<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
        x, y - 10, bar_w, hex(color), x + bar_w + 7, y, xml_escaped(label));
    y += 18;
  };
  if (scale.special_below) swatch(scale.special, scale.special_label);
  if (has_unmeasured)
    swatch(kUnmeasured, coloring == FaceColoring::angle_deviation ? "triangle (not measured)" : "not measured");
  swatch(shaded(kPlain, -1.0), "back side (greyed)");
  return svg;
}

/// One caption line about what the colours show, from the quality figures.
std::string coloring_caption(const QuadQuality& q, const MeshPictureOptions& options) {
  switch (options.coloring) {
    case FaceColoring::scaled_jacobian:
      return fmt::format("scaled Jacobian (Verdict): min {:.3f}, mean {:.3f}; {} inverted", q.min_scaled_jacobian,
                         q.mean_scaled_jacobian, q.inverted);
    case FaceColoring::angle_deviation:
      return fmt::format("corner angle deviation |angle - 90|: mean {:.2f} deg, p99 {:.2f} deg, max {:.2f} deg",
                         q.angle_dev_mean, q.angle_dev_p99, q.angle_dev_max);
    case FaceColoring::size:
      return fmt::format("edge length: mean {:.4g} = {:.2f} x the size {}", q.edge_length_mean,
                         q.edge_length_mean / options.size,
                         options.size_label.empty() ? fmt::format("{:.4g}", options.size) : options.size_label);
    case FaceColoring::none:
      break;
  }
  return fmt::format("edge length: mean {:.4g}, min {:.4g}, max {:.4g}", q.edge_length_mean, q.edge_length_min,
                     q.edge_length_max);
}

/// The faces that show, painted farthest first; `shows` marks their points. Their
/// edges are drawn when the median edge is at least kMinEdgePx long on screen;
/// below it they would only darken the picture, and the faces are drawn without
/// anti-aliasing so that no seam shows between them.
std::string faces_group(const PolygonMesh& mesh, const std::vector<DrawnFace>& faces, const ColorScale& scale,
                        const std::vector<double>& values, double edge_px, std::vector<char>& shows) {
  std::string svg =
      edge_px >= kMinEdgePx
          ? fmt::format("<g id=\"faces\" stroke=\"#1a1a1a\" stroke-width=\"{:.2f}\" stroke-linejoin=\"round\">\n",
                        std::clamp(edge_px / 14, 0.15, 0.8))
          : std::string("<g id=\"faces\" stroke=\"none\" shape-rendering=\"crispEdges\">\n");
  shows.assign(mesh.points.size(), 0);
  for (const DrawnFace& face : faces) {
    svg += polygon(face, shaded(color_of(scale, values[static_cast<std::size_t>(face.face)]), face.facing));
    for (int v : mesh.faces[static_cast<std::size_t>(face.face)])
      shows[static_cast<std::size_t>(v)] = 1;
  }
  return svg + "</g>\n";
}

/// A circle on every interior irregular vertex that shows; counts them all by
/// valence class into `by_class` and the marked ones into `marked`.
std::string singular_group(const PolygonMesh& mesh, const std::vector<char>& shows, const View& view,
                           const Frame& frame, double radius, std::map<int, std::size_t>& by_class,
                           std::size_t& marked) {
  std::string svg = "<g id=\"singular\" stroke=\"#000000\" stroke-width=\"1\">\n";
  for (const IrregularVertex& x : irregular_vertices(mesh)) {
    if (x.boundary) continue;
    ++by_class[valence_class(x.valence)];
    if (!shows[static_cast<std::size_t>(x.vertex)]) continue;
    ++marked;
    const Vec2 p = picture_point(mesh.points[static_cast<std::size_t>(x.vertex)], view, frame);
    svg += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" fill=\"{}\" data-vertex=\"{}\" data-valence=\"{}\"/>\n",
        p.x(), p.y(), radius, valence_fill(x.valence), x.vertex, x.valence);
  }
  return svg + "</g>\n";
}

/// The legend at (x, y): the colours, then the markers; `y` ends below it.
std::string legend_group(const ColorScale& scale, FaceColoring coloring, bool has_unmeasured,
                         const std::map<int, std::size_t>& by_class, double x, double& y) {
  std::string svg = "<g id=\"legend\">\n";
  svg += color_legend(scale, coloring, has_unmeasured, x, y);
  y += 8;
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-weight=\"bold\">interior irregular vertices</text>\n", x,
                     y);
  y += 20;
  if (by_class.empty()) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">none</text>\n", x, y);
    y += 18;
  }
  for (const auto& [valence, count] : by_class) {
    svg += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"5\" fill=\"{}\" stroke=\"#000000\"/>"
        "<text x=\"{:.1f}\" y=\"{:.1f}\">valence {}: {}</text>\n",
        x + 8, y - 4, valence_fill(valence), x + 23, y, valence_name(valence), count);
    y += 18;
  }
  return svg + "</g>\n";
}

/// The caption's lines: counts, irregular vertices, the colours' figures, the view.
std::vector<std::string> caption_lines(const QuadQuality& q, const MeshPictureOptions& options, const View& view,
                                       std::size_t faces_drawn, double edge_px,
                                       const std::map<int, std::size_t>& by_class) {
  std::vector<std::string> classes;
  for (const auto& [valence, count] : by_class)
    classes.push_back(fmt::format("{}: {}", valence_name(valence), count));
  const std::string others = q.other_faces > 0 ? fmt::format(", {} other faces", q.other_faces) : "";
  return {fmt::format("{} quads, {} triangles{}, {} vertices; {} faces shown", q.quads, q.triangles, others,
                      q.vertices, faces_drawn),
          fmt::format("irregular vertices: {} interior{}, {} boundary (not marked)", q.irregular_interior,
                      classes.empty() ? "" : fmt::format(" (valence {})", fmt::join(classes, ", ")),
                      q.irregular_boundary),
          coloring_caption(q, options),
          fmt::format("seen from ({:.3f}, {:.3f}, {:.3f}) (--view), hidden faces removed{}", view.toward_viewer.x(),
                      view.toward_viewer.y(), view.toward_viewer.z(),
                      edge_px >= kMinEdgePx ? std::string()
                                            : fmt::format("; edges not drawn (median {:.1f} px)", edge_px))};
}

}  // namespace

MeshPicture mesh_picture(const PolygonMesh& mesh, const QuadQuality& quality, const View& view, Frame frame,
                         const MeshPictureOptions& options) {
  frame.left = kPad;
  frame.top = kPad + kTitleHeight;
  const std::vector<DrawnFace> faces = visible_faces(mesh, view, frame);
  const ColorScale scale = color_scale(options.coloring);
  const std::vector<double> values = face_values(mesh, options.coloring, options.size);
  bool has_unmeasured = false;
  for (const DrawnFace& face : faces)
    has_unmeasured = has_unmeasured ||
                     (std::isnan(values[static_cast<std::size_t>(face.face)]) && options.coloring != FaceColoring::none);
  const double edge_px = median_edge_px(faces);  // strokes and markers follow the quads' size on screen

  MeshPicture picture;
  picture.faces_drawn = faces.size();
  std::vector<char> shows;
  std::string body = faces_group(mesh, faces, scale, values, edge_px, shows);
  std::map<int, std::size_t> by_class;
  body += singular_group(mesh, shows, view, frame, std::clamp(0.35 * edge_px, 1.2, 5.0), by_class, picture.marked);
  const double legend_x = frame.left + frame.width + 2 * kPad;
  double legend_y = frame.top + 12;
  body += legend_group(scale, options.coloring, has_unmeasured, by_class, legend_x, legend_y);

  double caption_y = std::max(frame.top + frame.height, legend_y) + kPad + 12;
  const std::vector<std::string> lines = caption_lines(quality, options, view, faces.size(), edge_px, by_class);
  const char* ids[] = {"caption-counts", "caption-irregular", "caption-figures", "caption-view"};
  for (std::size_t i = 0; i < lines.size(); ++i) {
    body += fmt::format("<text id=\"{}\" x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\">{}</text>\n", ids[i], kPad,
                        caption_y, xml_escaped(lines[i]));
    caption_y += kCaptionLine;
  }

  const double width = legend_x + kLegendWidth, height = caption_y + kPad;
  picture.svg = fmt::format(
                    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
                    "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" font-size=\"12\">\n"
                    "<title>{2}</title>\n"
                    "<rect width=\"{0:.0f}\" height=\"{1:.0f}\" fill=\"white\"/>\n"
                    "<text id=\"title\" x=\"{3:.1f}\" y=\"{4:.1f}\" font-size=\"15\" font-weight=\"bold\">{2}</text>\n",
                    width, height, xml_escaped(options.title), kPad, kPad + 16) +
                body + "</svg>\n";
  return picture;
}

}  // namespace qm::tools
