// bench_mesh: stage times of the whole quad-meshing job (`quadmesh mesh --singularities abel` without
// reading and writing), as ratios against its forms stage measured in the same
// run (issue 4: the whole mesh stage within about 3x of the forms stage).
//
//   bench_mesh [FILE] [--size P%] [--auto] [--repeat N]
// FILE defaults to the shared bunny-open-large.obj (278k triangles). With --auto the
// job runs again with --singularities auto, and its time is printed as a ratio
// against the Abel run (issue 18: the cones within about 2x of it). With --repeat
// N each job runs N times, the two alternating, and the shortest run of each is
// the one printed: on a shared machine whose load comes and goes, the load moves
// both alike. A CAD input (.geo, .step, ...) is triangulated for the quad size
// asked for, as `quadmesh mesh` triangulates it.
#include "io/read_surface.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "libquadmesh/topology/applicability.h"
#include "tools/common/heap_settings.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <utility>

int main(int argc, char** argv) {
  qm::tools::keep_freed_memory();  // as quadmesh does
  CLI::App app{"Stage times of the quad mesher against its forms stage"};
  std::string file = std::string(QM_DATA_DIR) + "/bunny-open-large.obj";
  double percent = 1.5;
  app.add_option("FILE", file, "Input surface");
  app.add_option("--size", percent, "Quad size in percent of the bounding-box diagonal")
      ->check(CLI::PositiveNumber);
  bool automatic = false;
  app.add_flag("--auto", automatic, "Also run --singularities auto and print its time against the Abel run's");
  int repeat = 1;
  app.add_option("--repeat", repeat, "Run each job this many times, alternating, and keep the shortest of each")
      ->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);
  try {
    // a CAD input triangulated for this quad size, as `quadmesh mesh --size` does
    qm::io::ReadOptions read;
    read.quad_size_relative = percent / 100.0;
    const qm::AnalyzedSurface surface = qm::analyze_topology(qm::io::read_surface(file, read).soup);
    qm::require_supported(surface);
    qm::QuadMeshOptions options;
    options.size_relative = percent / 100.0;
    // one job's result and wall-clock seconds
    const auto timed = [&](qm::Singularities singularities) {
      options.singularities = singularities;
      const auto start = std::chrono::steady_clock::now();
      qm::QuadMeshResult result = qm::mesh_quads(surface.soup, options);
      return std::make_pair(std::move(result),
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    };
    // the baseline, the seed's method (abel), and auto, alternating; the shortest of each kept
    std::pair<qm::QuadMeshResult, double> abel, cones;
    for (int run = 0; run < repeat; ++run) {
      auto once = timed(qm::Singularities::abel);
      if (run == 0 || once.second < abel.second) abel = std::move(once);
      if (!automatic) continue;
      once = timed(qm::Singularities::automatic);
      if (run == 0 || once.second < cones.second) cones = std::move(once);
    }
    const qm::QuadMeshResult& r = abel.first;
    const double total = abel.second;
    // stages in order of first appearance, summed over the attempts of --form auto
    std::vector<std::pair<std::string, double>> stages;
    for (const auto& [name, s] : r.timings) {
      auto it = std::find_if(stages.begin(), stages.end(), [&](const auto& p) { return p.first == name; });
      if (it == stages.end())
        stages.emplace_back(name, s);
      else
        it->second += s;
    }
    double forms = 0;
    for (const auto& [name, s] : stages)
      if (name == "forms") forms += s;
    fmt::print("input            {} ({} vertices, {} triangles, doubled genus {})\n", file,
               surface.soup.points.size(), surface.soup.triangles.size(), r.doubled_genus);
    fmt::print("output           {} quads at {}% of the diagonal ({} form(s) tried)\n", r.quads.quads.size(), percent,
               r.form_attempts);
    fmt::print("forms stage      {:.3f} s  = 1.00\n", forms);
    for (const auto& [name, s] : stages)
      if (name != "forms") fmt::print("  {:<16} {:.3f} s  = {:.2f}\n", name, s, s / forms);
    fmt::print("whole mesh job   {:.3f} s  = {:.2f} x the forms stage\n", total, total / forms);
    if (repeat > 1) fmt::print("(the shortest of {} runs of each, alternating)\n", repeat);
    if (automatic) {
      const qm::QuadMeshResult& a = cones.first;
      const double seconds = cones.second;
      fmt::print("singularities auto {:.3f} s  = {:.2f} x the Abel run ({} route, {} quads, {:.0f}% in the size band{})\n",
                 seconds, seconds / total, a.singularities, a.quads.quads.size(), 100 * a.size_band_share,
                 a.cone_route_failure.empty() ? std::string() : "; cones not kept: " + a.cone_route_failure);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench_mesh: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
