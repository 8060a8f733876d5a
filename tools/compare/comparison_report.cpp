#include "tools/compare/comparison_report.h"

#include "tools/compare/histogram_svg.h"
#include "tools/common/quality_json.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

namespace qm::tools {

namespace {

using Json = nlohmann::ordered_json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum class Better { none, lower, higher, input };

/// One column of the table (and one measure of the verdict).
struct Metric {
  const char* header;  ///< table header
  const char* words;   ///< in a sentence
  Better better;
  const char* format;  ///< fmt spec of one value
  std::function<double(const QuadQuality&)> of;
  bool in_verdict = true;
};

const std::vector<Metric>& metrics() {
  static const std::vector<Metric> all = {
      {"quads", "quads", Better::none, "{:.0f}",
       [](const QuadQuality& q) { return static_cast<double>(q.quads); }, false},
      {"edge mean", "mean edge length", Better::none, "{:.3g}",
       [](const QuadQuality& q) { return q.edge_length_mean; }, false},
      {"triangles", "triangles left", Better::lower, "{:.0f}",
       [](const QuadQuality& q) { return static_cast<double>(q.triangles); }},
      {"inverted", "inverted quads", Better::lower, "{:.0f}",
       [](const QuadQuality& q) { return static_cast<double>(q.inverted); }},
      {"min SJ", "min scaled Jacobian", Better::higher, "{:.3f}",
       [](const QuadQuality& q) { return q.min_scaled_jacobian; }},
      {"mean SJ", "mean scaled Jacobian", Better::higher, "{:.3f}",
       [](const QuadQuality& q) { return q.mean_scaled_jacobian; }},
      {"min angle", "min angle", Better::higher, "{:.1f}", [](const QuadQuality& q) { return q.min_angle; }, false},
      {"max angle", "max angle", Better::lower, "{:.1f}", [](const QuadQuality& q) { return q.max_angle; }, false},
      {"min warpage", "min warpage", Better::higher, "{:.3f}",
       [](const QuadQuality& q) { return q.min_warpage; }, false},
      {"max aspect", "max aspect ratio", Better::lower, "{:.2f}",
       [](const QuadQuality& q) { return q.aspect_ratio_max; }, false},
      {"max skew", "max skew", Better::lower, "{:.3f}", [](const QuadQuality& q) { return q.skew_max; }, false},
      {"max taper", "max taper", Better::lower, "{:.3f}", [](const QuadQuality& q) { return q.taper_max; }, false},
      {"angle dev. mean", "mean angle deviation", Better::lower, "{:.2f}",
       [](const QuadQuality& q) { return q.angle_dev_mean; }},
      {"angle dev. p99", "99th-percentile angle deviation", Better::lower, "{:.2f}",
       [](const QuadQuality& q) { return q.angle_dev_p99; }},
      {"irregular vertices", "irregular interior vertices", Better::lower, "{:.0f}",
       [](const QuadQuality& q) { return static_cast<double>(q.irregular_interior); }},
      {"boundary loops", "boundary loops", Better::input, "{:.0f}",
       [](const QuadQuality& q) { return static_cast<double>(q.boundary_loops); }, false},
      {"chi", "Euler characteristic", Better::input, "{:.0f}",
       [](const QuadQuality& q) { return static_cast<double>(q.euler_characteristic); }, false},
      {"Hausdorff", "Hausdorff distance", Better::lower, "{:.2e}",
       [](const QuadQuality& q) { return q.hausdorff_rel; }},
      {"in size band", "share of the quads within [0.5, 2] x the size", Better::higher, "{:.3f}",
       [](const QuadQuality& q) { return q.size_band_share; }, false},
      {"max size", "largest quad size / the size", Better::lower, "{:.2f}",
       [](const QuadQuality& q) { return q.size_ratio_max; }, false},
      {"corners wrong", "corners not in max(1, round(angle / 90 deg)) quads", Better::lower, "{:.0f}",
       [](const QuadQuality& q) { return static_cast<double>(corners_wrong(q)); }, false},
  };
  return all;
}

std::string shown(double x, const char* spec) {
  return std::isfinite(x) ? fmt::format(fmt::runtime(spec), x) : std::string("n/a");
}

/// The value as the table shows it (so that ties look like ties).
double rounded(double x, const char* spec) {
  return std::isfinite(x) ? std::stod(fmt::format(fmt::runtime(spec), x)) : kNaN;
}

double metric_value(const MethodRun& run, const Metric& m) {
  return run.quality ? rounded(m.of(*run.quality), m.format) : kNaN;
}

double input_value(const ComparisonReport& r, const Metric& m) {
  return std::string(m.header) == "chi" ? r.reference_euler_characteristic
                                        : r.reference_boundary_loops;
}

/// The best shown value of `m` over the measured rows (NaN: none, or no order).
double best_of(const ComparisonReport& r, const Metric& m,
               const std::function<bool(const MethodRun&)>& among) {
  double best = kNaN;
  if (m.better != Better::lower && m.better != Better::higher) return best;
  for (const MethodRun& run : r.runs) {
    if (!among(run)) continue;
    const double v = metric_value(run, m);
    if (std::isnan(v)) continue;
    if (std::isnan(best) || (m.better == Better::lower ? v < best : v > best)) best = v;
  }
  return best;
}

bool is_best(const ComparisonReport& r, const MethodRun& run, const Metric& m) {
  const double v = metric_value(run, m);
  if (std::isnan(v)) return false;
  if (m.better == Better::input) return v == input_value(r, m);
  return v == best_of(r, m, [](const MethodRun& x) { return x.quality.has_value(); });
}

/// The meshes' pictures side by side, three to a row (a Markdown table whose
/// header row holds the first three names); a method without a picture says why.
std::string pictures_markdown(const ComparisonReport& r) {
  constexpr std::size_t kPerRow = 3;
  struct Cell {
    std::string name, content;
  };
  std::vector<Cell> cells;
  for (const MethodRun& run : r.runs)
    cells.push_back({run.method.name, run.picture.empty()
                                          ? fmt::format("no mesh: {}{}", status_name(run.status),
                                                        run.detail.empty() ? "" : ": " + run.detail)
                                          : fmt::format("![{0}]({1})", run.method.name, picture_file(run.method))});
  for (const Method& method : r.skipped)
    cells.push_back({method.name, "skipped: " + method.skipped_because});
  if (cells.empty()) return "";
  std::string md = fmt::format(
      "**The meshes**, all seen from ({:.3f}, {:.3f}, {:.3f}) (the direction that shows the most of the input) "
      "at the same scale, coloured by Verdict's scaled Jacobian; interior vertices of valence other than 4 are "
      "marked (3 black, 5 white, 6 and more magenta). Hidden faces are removed.\n\n",
      r.view.x(), r.view.y(), r.view.z());
  const auto escaped_cell = [](std::string text) {
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
      text.replace(at, 1, "\\|");
    return text;
  };
  for (std::size_t row = 0; row * kPerRow < cells.size(); ++row) {
    std::string names = "|", contents = "|";
    for (std::size_t k = row * kPerRow; k < (row + 1) * kPerRow; ++k) {
      const std::string name = row == 0 ? fmt::format("`{}`", cells[k < cells.size() ? k : 0].name)
                                         : fmt::format("**`{}`**", cells[k < cells.size() ? k : 0].name);
      names += k < cells.size() ? " " + name + " |" : std::string(" |");
      contents += k < cells.size() ? fmt::format(" {} |", escaped_cell(cells[k].content)) : std::string(" |");
    }
    md += names + "\n";
    if (row == 0) md += "|---|---|---|\n";
    md += contents + "\n";
  }
  return md + "\n";
}

bool ours(const MethodRun& run) {
  return run.method.name.rfind("quadmesh", 0) == 0;
}

std::string seconds_text(double s) {
  return fmt::format("{:.2f}", s);
}

}  // namespace

std::string picture_file(const Method& method) { return method.name + ".svg"; }

Json report_json(const ComparisonReport& r) {
  Json j;
  j["input"] = r.input;
  j["size"] = r.size;
  j["diagonal"] = r.diagonal;
  j["reference"] = {{"points", r.reference_points},
                    {"triangles", r.reference_triangles},
                    {"euler_characteristic", r.reference_euler_characteristic},
                    {"boundary_loops", r.reference_boundary_loops}};
  j["timeout"] = r.timeout_seconds;
  j["gmsh_version"] = r.gmsh_version;
  j["gmsh_program"] = r.gmsh_program;
  Json methods = Json::array();
  for (const MethodRun& run : r.runs) {
    Json m;
    m["name"] = run.method.name;
    m["status"] = status_name(run.status);
    m["seconds"] = run.seconds;
    m["detail"] = run.detail;
    m["description"] = run.method.description;
    m["mesh"] = run.quality ? Json(run.method.mesh_file) : Json(nullptr);
    m["picture"] = run.picture.empty() ? Json(nullptr) : Json(picture_file(run.method));
    if (run.quality) {
      // the keys, taken from the one quality JSON (irregular_vertices: interior)
      const Json all = quality_json(*run.quality);
      Json quality;
      for (const char* key : {"quads", "triangles", "inverted", "min_scaled_jacobian", "mean_scaled_jacobian",
                              "min_angle", "max_angle", "min_warpage", "aspect_ratio_max", "skew_max", "taper_max",
                              "triangle_min_scaled_jacobian", "angle_dev_mean", "angle_dev_p99", "irregular_vertices", "boundary_loops",
                              "euler_characteristic", "hausdorff_rel", "edge_length_mean", "size_band_share",
                              "size_ratio_max", "corners"})
        quality[key] = all[std::string(key) == "irregular_vertices" ? "irregular_interior" : key];
      m["quality"] = std::move(quality);
    } else {
      m["quality"] = nullptr;
    }
    methods.push_back(std::move(m));
  }
  j["methods"] = std::move(methods);
  Json skipped = Json::array();
  for (const Method& method : r.skipped)
    skipped.push_back({{"name", method.name}, {"reason", method.skipped_because}, {"description", method.description}});
  j["skipped"] = std::move(skipped);
  j["view"] = {r.view.x(), r.view.y(), r.view.z()};
  return j;
}

std::string report_verdict(const ComparisonReport& r) {
  std::vector<std::string> sentences;
  std::vector<std::string> failures;
  for (const MethodRun& run : r.runs)
    if (!run.quality)
      failures.push_back(fmt::format("{}, {}: {}", run.method.name, status_name(run.status),
                                     run.detail.empty() ? "no mesh" : run.detail));
  if (!failures.empty())
    sentences.push_back(fmt::format("No mesh from: {}.", fmt::join(failures, "; ")));
  for (const Method& method : r.skipped)
    sentences.push_back(fmt::format("Not run: {}: {}.", method.name, method.skipped_because));

  const MethodRun* mine = nullptr;
  for (const MethodRun& run : r.runs)
    if (ours(run)) mine = &run;
  const auto baseline_ok = [](const MethodRun& run) { return !ours(run) && run.quality; };
  bool any_baseline = false;
  for (const MethodRun& run : r.runs)
    any_baseline = any_baseline || baseline_ok(run);

  if (mine == nullptr || !mine->quality) {
    sentences.push_back(
        "quadmesh produced no mesh on this input, so the table compares Gmsh's methods only "
        "(see quadmesh.log for its message).");
    return fmt::format("{}", fmt::join(sentences, " "));
  }
  const QuadQuality& q = *mine->quality;
  if (any_baseline) {
    std::vector<std::string> wins, losses;
    std::size_t measures = 0;
    for (const Metric& m : metrics()) {
      if (!m.in_verdict) continue;
      ++measures;
      const double v = metric_value(*mine, m);
      const double best = best_of(r, m, baseline_ok);
      if (std::isnan(v)) continue;
      if (std::isnan(best) || (m.better == Better::lower ? v <= best : v >= best)) {
        wins.push_back(m.words);
        continue;
      }
      for (const MethodRun& run : r.runs)
        if (baseline_ok(run) && metric_value(run, m) == best) {
          losses.push_back(fmt::format("{} ({} {} against {})", m.words, run.method.name,
                                       shown(best, m.format), shown(v, m.format)));
          break;
        }
    }
    sentences.push_back(
        fmt::format("quadmesh is best or tied on {} of {} quality measures{}.", wins.size(),
                    measures, wins.empty() ? "" : fmt::format(" ({})", fmt::join(wins, ", "))));
    sentences.push_back(
        losses.empty() ? std::string("No Gmsh method beats it on any of them.")
                       : fmt::format("A Gmsh method does better on: {}.", fmt::join(losses, "; ")));
  }
  const bool same_topology = q.euler_characteristic == r.reference_euler_characteristic &&
                             q.boundary_loops == r.reference_boundary_loops;
  sentences.push_back(fmt::format(
      "Its mesh is {} ({} quads, {} triangles) and {} the input's topology (chi {}, {} boundary "
      "loops{}).",
      q.triangles == 0 && q.other_faces == 0 ? "pure quad" : "quad-dominant", q.quads, q.triangles,
      same_topology ? "keeps" : "does NOT keep", q.euler_characteristic, q.boundary_loops,
      same_topology ? ""
                    : fmt::format("; the input has chi {}, {} loops",
                                  r.reference_euler_characteristic, r.reference_boundary_loops)));
  std::vector<std::string> changed;
  for (const MethodRun& run : r.runs)
    if (baseline_ok(run) &&
        (run.quality->euler_characteristic != r.reference_euler_characteristic ||
         run.quality->boundary_loops != r.reference_boundary_loops))
      changed.push_back(run.method.name);
  if (!changed.empty())
    sentences.push_back(fmt::format("Topology changed by: {}.", fmt::join(changed, ", ")));
  if (any_baseline) {
    double fastest = std::numeric_limits<double>::infinity(), slowest = 0;
    for (const MethodRun& run : r.runs)
      if (baseline_ok(run)) {
        fastest = std::min(fastest, run.seconds);
        slowest = std::max(slowest, run.seconds);
      }
    sentences.push_back(
        fmt::format("It took {:.2f} s; the Gmsh methods that finished {:.2f} to {:.2f} s.",
                    mine->seconds, fastest, slowest));
  }
  return fmt::format("{}", fmt::join(sentences, " "));
}

std::string report_markdown(const ComparisonReport& r) {
  std::string md =
      fmt::format("# quadmesh compare: {}\n\n", std::filesystem::path(r.input).filename().string());
  md += fmt::format(
      "Input `{}`; target quad size {:.4g} ({:.3g}% of the bounding-box diagonal {:.4g}). "
      "Every row is measured by the same quality module against the same reference, the input "
      "triangulation (`input.msh`: {} points, {} triangles, chi {}, {} boundary loops); times are "
      "wall-clock seconds of each method's own process in this run (limit {:g} s). Every Gmsh row ran "
      "`{}`, Gmsh {}.\n\n",
      r.input, r.size, 100.0 * r.size / r.diagonal, r.diagonal, r.reference_points,
      r.reference_triangles, r.reference_euler_characteristic, r.reference_boundary_loops,
      r.timeout_seconds, r.gmsh_program.empty() ? "gmsh" : r.gmsh_program,
      r.gmsh_version.empty() ? "version unknown" : r.gmsh_version);

  md += "| method | status | seconds |";
  for (const Metric& m : metrics())
    md += fmt::format(" {} |", m.header);
  md += "\n|---|---|---:|";
  for (std::size_t i = 0; i < metrics().size(); ++i)
    md += "---:|";
  md += "\n";
  double fastest = kNaN;
  for (const MethodRun& run : r.runs)
    if (run.quality && (std::isnan(fastest) || run.seconds < fastest)) fastest = run.seconds;
  for (const MethodRun& run : r.runs) {
    const bool quickest = run.quality && seconds_text(run.seconds) == seconds_text(fastest);
    md +=
        fmt::format("| `{}` | {} | {} |", run.method.name, status_name(run.status),
                    quickest ? "**" + seconds_text(run.seconds) + "**" : seconds_text(run.seconds));
    for (const Metric& m : metrics()) {
      if (!run.quality) {
        md += " - |";
        continue;
      }
      const std::string text = shown(m.of(*run.quality), m.format);
      md += is_best(r, run, m) ? fmt::format(" **{}** |", text) : fmt::format(" {} |", text);
    }
    md += "\n";
  }
  for (const Method& method : r.skipped) {
    md += fmt::format("| `{}` | skipped | - |", method.name);
    for (std::size_t i = 0; i < metrics().size(); ++i)
      md += " - |";
    md += "\n";
  }
  md +=
      "\n**Bold**: the best value of the rows with a mesh (for boundary loops and chi: equal to "
      "the input's). Every shape figure of a quad is Verdict's (VTK's vtkMeshQuality, ParaView, "
      "Cubit): SJ, its scaled Jacobian (min over its corners against the quad's own normal; 1 = "
      "rectangle, <= 0 = inverted); min and max angle in degrees; warpage (1 = planar, <= 0 = "
      "folded); aspect ratio (1 = square); skew (0 = orthogonal axes); taper (0 = parallelogram). "
      "Angle deviation: |corner angle - 90| in degrees over all quad corners. "
      "Edge mean: mean edge length, to set against the target size. "
      "Irregular vertices: interior vertices with valence other than 4. Hausdorff: two-sided "
      "distance to the input triangulation / its bounding-box diagonal. In size band: share of "
      "the quads whose mean edge is within [0.5, 2] x the target size; max size: the largest such ratio. "
      "Corners wrong: the input's corners (more than 45 degrees from straight) not in max(1, round(angle / "
      "90 deg)) quads. Triangles are counted, not measured.\n\n";
  md += fmt::format("**Verdict.** {}\n\n", report_verdict(r));
  md += pictures_markdown(r);
  md += fmt::format("![Angle deviation of every method]({})\n\n", kAngleHistogramFile);
  md += fmt::format("![Scaled Jacobian of every method]({})\n\n", kJacobianHistogramFile);
  md += "## Methods\n\n";
  for (const MethodRun& run : r.runs) {
    md += fmt::format("- `{}`: {}. Files: `{}`", run.method.name, run.method.description,
                      run.method.mesh_file);
    if (!run.method.script_file.empty()) md += fmt::format(", `{}`", run.method.script_file);
    md += fmt::format(", `{}.log`.", run.method.name);
    if (!run.quality) md += fmt::format(" **{}**: {}.", status_name(run.status), run.detail);
    md += "\n";
  }
  for (const Method& method : r.skipped)
    md += fmt::format("- `{}`: {}. **skipped**: {}.\n", method.name, method.description, method.skipped_because);
  md +=
      "\nOpen the meshes side by side: `gmsh quadmesh.msh gmsh-frontal-blossom.msh` "
      "(Tools > Statistics; Tools > Options > Mesh > Visibility).\n";
  return md;
}

namespace {

std::string histogram_picture(const ComparisonReport& r, const HistogramPicture& picture,
                              const std::function<Histogram(const MethodRun&)>& of) {
  std::vector<HistogramSeries> series;
  for (const MethodRun& run : r.runs) {
    HistogramSeries s;
    s.name = run.method.name;
    s.present = run.quality.has_value();
    if (s.present)
      s.histogram = of(run);
    else
      s.note = fmt::format("{}: no mesh", status_name(run.status));
    series.push_back(std::move(s));
  }
  return histogram_svg(picture, series);
}

}  // namespace

std::string angle_histogram_svg(const ComparisonReport& r) {
  HistogramPicture picture;
  picture.title = fmt::format("Corner angle deviation |angle - 90 deg| ({})",
                              std::filesystem::path(r.input).filename().string());
  picture.x_label = "deviation from 90 degrees (2.5-degree bins; the last holds everything above)";
  picture.y_label = "share of the quad corners";
  picture.unit = "quad corners";
  return histogram_picture(r, picture, [](const MethodRun& run) {
    return make_histogram(run.samples.angle_deviation_deg, 0.0, 90.0, 36);
  });
}

std::string jacobian_histogram_svg(const ComparisonReport& r) {
  HistogramPicture picture;
  picture.title = fmt::format("Scaled Jacobian per quad ({})",
                              std::filesystem::path(r.input).filename().string());
  picture.x_label =
      "Verdict scaled Jacobian of the quad (1 = square; the first bin holds the inverted)";
  picture.y_label = "share of the quads (log scale)";
  picture.log_y = true;
  return histogram_picture(r, picture, [](const MethodRun& run) {
    return make_histogram(run.samples.scaled_jacobian, 0.0, 1.0, 40);
  });
}

}  // namespace qm::tools
