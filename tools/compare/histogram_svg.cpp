#include "tools/compare/histogram_svg.h"

#include "tools/common/xml_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace qm::tools {

Histogram make_histogram(const std::vector<double>& values, double lo, double hi, int bins) {
  Histogram h;
  h.lo = lo;
  h.hi = hi;
  h.fractions.assign(static_cast<std::size_t>(std::max(bins, 1)), 0.0);
  const double width = (hi - lo) / static_cast<double>(h.fractions.size());
  for (double v : values) {
    if (std::isnan(v)) continue;
    const double slot = std::floor((v - lo) / width);
    const auto last = static_cast<double>(h.fractions.size() - 1);
    h.fractions[static_cast<std::size_t>(std::clamp(slot, 0.0, last))] += 1.0;
    ++h.count;
  }
  if (h.count > 0)
    for (double& f : h.fractions)
      f /= static_cast<double>(h.count);
  return h;
}

namespace {

/// A tick step of 1, 2 or 5 times a power of ten giving about `target` ticks.
double nice_step(double range, int target) {
  const double raw = range / target;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

// Ours first and strongest; the baselines in distinct, colour-blind-safe hues.
const char* const kColors[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd",
                               "#ff7f0e", "#8c564b", "#17becf"};

}  // namespace

std::string histogram_svg(const HistogramPicture& picture,
                          const std::vector<HistogramSeries>& series) {
  const double width = 800, height = 380;
  const double left = 64, right = 290, top = 40, bottom = 52;  // the legend is on the right
  const double plot_w = width - left - right, plot_h = height - top - bottom;

  double lo = 0, hi = 1, peak = 0;
  for (const HistogramSeries& s : series) {
    if (!s.present) continue;
    lo = s.histogram.lo;
    hi = s.histogram.hi;
    for (double f : s.histogram.fractions)
      peak = std::max(peak, f);
  }
  // Linear: 0 to a round value above the peak (at most 100%). Log: 1e-4 to 1.
  const double y_step = nice_step(std::max(peak, 0.01), 5);
  const double y_max = std::min(std::ceil(std::max(peak, 0.01) * 1.05 / y_step) * y_step, 1.0);
  const double log_floor = 1e-4;
  const auto x_of = [&](double x) { return left + (x - lo) / (hi - lo) * plot_w; };
  const auto y_of = [&](double y) {
    if (picture.log_y)
      return top + plot_h -
             std::log10(std::max(y, log_floor) / log_floor) / std::log10(1.0 / log_floor) * plot_h;
    return top + plot_h - y / y_max * plot_h;
  };
  std::vector<double> y_ticks;
  if (picture.log_y)
    y_ticks = {1e-4, 1e-3, 1e-2, 1e-1, 1.0};
  else
    for (double y = 0; y <= y_max + 1e-12; y += y_step)
      y_ticks.push_back(y);

  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
      "<text x=\"{2}\" y=\"24\" font-size=\"15\" font-weight=\"bold\">{3}</text>\n",
      width, height, left, xml_escaped(picture.title));

  // grid and axes
  for (double y : y_ticks) {
    svg += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n"
        "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:g}%</text>\n",
        left, y_of(y), left + plot_w, y_of(y), left - 6, y_of(y) + 4, std::round(y * 1e6) / 1e4);
  }
  const double x_step = nice_step(hi - lo, 8);
  for (double x = std::ceil(lo / x_step) * x_step; x <= hi + 1e-12; x += x_step) {
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#999\"/>\n"
        "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4:g}</text>\n",
        x_of(x), top + plot_h, top + plot_h + 5, top + plot_h + 18, std::round(x * 1000) / 1000);
  }
  svg += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
      "stroke=\"#999\"/>\n"
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n"
      "<text transform=\"translate(16 {:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      left, top, plot_w, plot_h, left + plot_w / 2, height - 12, xml_escaped(picture.x_label),
      top + plot_h / 2, xml_escaped(picture.y_label));

  // one step line per method, and the legend
  double legend_y = top + 8;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const HistogramSeries& s = series[i];
    const char* color = kColors[i % (sizeof kColors / sizeof kColors[0])];
    const double stroke = i == 0 ? 2.5 : 1.6;
    if (s.present && s.histogram.count > 0) {
      const std::size_t bins = s.histogram.fractions.size();
      std::string points = fmt::format("{:.1f},{:.1f}", x_of(lo), y_of(0));
      for (std::size_t b = 0; b < bins; ++b) {
        const double x0 = lo + (hi - lo) * static_cast<double>(b) / static_cast<double>(bins);
        const double x1 = lo + (hi - lo) * static_cast<double>(b + 1) / static_cast<double>(bins);
        const double y = y_of(s.histogram.fractions[b]);
        points += fmt::format(" {:.1f},{:.1f} {:.1f},{:.1f}", x_of(x0), y, x_of(x1), y);
      }
      points += fmt::format(" {:.1f},{:.1f}", x_of(hi), y_of(0));
      svg += fmt::format(
          "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" "
          "stroke-linejoin=\"round\" opacity=\"0.9\"/>\n",
          points, color, stroke);
    }
    const double lx = left + plot_w + 14;
    const bool drawn = s.present && s.histogram.count > 0;
    svg += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
        "stroke-width=\"{}\"{}/>\n"
        "<text x=\"{:.1f}\" y=\"{:.1f}\"{}>{}</text>\n",
        lx, legend_y, lx + 22, legend_y, drawn ? color : "#bbb", stroke,
        drawn ? "" : " stroke-dasharray=\"3 3\"", lx + 28, legend_y + 4,
        drawn ? "" : " fill=\"#888\"", xml_escaped(s.name));
    const std::string note = drawn ? fmt::format("{} {}", s.histogram.count, picture.unit)
                                   : (s.note.empty() ? std::string("no mesh") : s.note);
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\">{}</text>\n",
                       lx + 28, legend_y + 17, xml_escaped(note));
    legend_y += 36;
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace qm::tools
