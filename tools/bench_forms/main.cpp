// bench_forms: stage times of the forms stage, as ratios against a baseline measured
// in the same run: one factorization of the cotangent Laplacian of the doubled
// surface plus 2G back-solves (the floor the method's cost should approach).
//
//   bench_forms [FILE] [--repeat N]
// FILE defaults to the shared bunny-open-large.obj (278k triangles).
#include "io/read_surface.h"
#include "libquadmesh/forms/boundary_chords.h"
#include "libquadmesh/forms/cohomology_basis.h"
#include "libquadmesh/forms/harmonic_basis.h"
#include "libquadmesh/forms/symmetric_forms.h"
#include "libquadmesh/topology/applicability.h"
#include "tools/common/heap_settings.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Stage times of the forms stage against one factorization + 2G back-solves"};
  std::string file = std::string(QM_DATA_DIR) + "/bunny-open-large.obj";
  int repeat = 3;
  bool system_malloc = false;
  app.add_option("FILE", file, "Input surface");
  app.add_option("--repeat", repeat, "Runs per measurement (the minimum is kept)")->check(CLI::PositiveNumber);
  app.add_flag("--system-malloc", system_malloc, "Keep glibc's malloc defaults (freed memory back to the kernel)");
  CLI11_PARSE(app, argc, argv);
  if (!system_malloc) qm::tools::keep_freed_memory();

  try {
    auto t = std::chrono::steady_clock::now();
    qm::AnalyzedSurface surface = qm::analyze_topology(qm::io::read_surface(file).soup);
    qm::require_supported(surface);
    qm::split_boundary_chords(surface.soup);
    const qm::Mesh mesh = qm::to_surface_mesh(surface.soup);
    const double read_seconds = seconds_since(t);

    double baseline = 1e300, forms_total = 1e300;
    std::vector<std::pair<std::string, double>> stage;  // pipeline order, minimum over the runs
    int G = 0;
    for (int run = 0; run < repeat; ++run) {
      // baseline: factor + 2G back-solves on the doubled surface
      const qm::DoubledSurface d = qm::double_surface(mesh);
      const qm::CohomologyBasis c = qm::cohomology_basis(d.mesh);
      G = static_cast<int>(c.forms.cols() / 2);
      t = std::chrono::steady_clock::now();
      const qm::HarmonicSolver solver(d.mesh, qm::cotan_weights(d.mesh));
      const Eigen::MatrixXd omega = solver.harmonic(c.forms);
      baseline = std::min(baseline, seconds_since(t));

      t = std::chrono::steady_clock::now();
      const qm::SymmetricForms forms = qm::compute_symmetric_forms(mesh);
      forms_total = std::min(forms_total, seconds_since(t));
      if (stage.empty()) stage = forms.timings;
      for (std::size_t i = 0; i < stage.size(); ++i)
        stage[i].second = std::min(stage[i].second, forms.timings[i].second);
    }
    fmt::print("input            {} ({} vertices, {} triangles, doubled genus {})\n", file,
               mesh.number_of_vertices(), mesh.number_of_faces(), G);
    fmt::print("read + checks    {:.3f} s (not part of the ratio)\n", read_seconds);
    fmt::print("baseline         {:.3f} s  = 1.00  (factorization + {} back-solves)\n", baseline, 2 * G);
    for (const auto& [name, s] : stage) fmt::print("  {:<16} {:.3f} s  = {:.2f}\n", name, s, s / baseline);
    fmt::print("forms stage      {:.3f} s  = {:.2f} x baseline (minimum of {} runs)\n", forms_total,
               forms_total / baseline, repeat);
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench_forms: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
