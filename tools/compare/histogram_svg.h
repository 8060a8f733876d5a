// Histograms of several meshes' element qualities in one picture (SVG written by
// hand): one step line per method, so the shapes of the distributions compare at
// a glance.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace qm::tools {

/// Fractions of `values` in `bins` equal bins over [lo, hi]; values outside are
/// counted in the first or last bin (NaN values are skipped).
struct Histogram {
  double lo = 0, hi = 1;
  std::vector<double> fractions;  ///< sum 1, or all 0 without values
  std::size_t count = 0;          ///< values counted
};
Histogram make_histogram(const std::vector<double>& values, double lo, double hi, int bins);

/// One method in the picture. A method without a histogram (it produced no mesh)
/// is listed in the legend with `note` (e.g. "crashed: no mesh").
struct HistogramSeries {
  std::string name;
  Histogram histogram;
  bool present = true;
  std::string note;
};

struct HistogramPicture {
  std::string title;
  std::string x_label;
  std::string y_label = "share of the quads";
  std::string unit = "quads";  ///< what the values count, for the legend ("1787 quads")
  /// Logarithmic share axis (0.01% to 100%), for distributions piled up at one end
  /// whose tail matters; empty bins then sit on the bottom line.
  bool log_y = false;
};

/// A standalone SVG document (800 x 380 user units). Precondition: the present
/// series share lo, hi and the bin count.
std::string histogram_svg(const HistogramPicture& picture,
                          const std::vector<HistogramSeries>& series);

}  // namespace qm::tools
