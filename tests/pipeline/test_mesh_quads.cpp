// The quad mesher end to end (method.md sections 7-10): quantization invariants
// read off the parameterization, and the properties every output must have.
#include "io/read_surface.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"
#include "libquadmesh/forms/boundary_chords.h"
#include "libquadmesh/param/form_choice.h"
#include "libquadmesh/param/rounding_scale.h"
#include "libquadmesh/param/surface_forms.h"
#include "libquadmesh/pipeline/acceptance_criteria.h"
#include "libquadmesh/pipeline/internal/candidate_ranking.h"
#include "libquadmesh/pipeline/internal/quad_improvement.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/topology/topology_report.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace qm;

namespace {

double distance_to_integer(double x) { return std::abs(x - std::round(x)); }

/// An input file as `quadmesh mesh` sees it: read (CAD input triangulated for quads
/// of `quad_size_relative` of the diagonal; 0: the reader's default), checked, oriented.
/// These tests were written for the CAD triangulation of before issue 21 (triangles
/// a third of the quad size), whose roundings took the paths they check: pinned.
TriangleSoup analysed(const std::string& path, double quad_size_relative = 0) {
  io::ReadOptions read;
  read.quad_size_relative = quad_size_relative;
  read.cad_size_divisor = 3;
  return analyze_topology(io::read_surface(path, read).soup).soup;
}

/// The options of the seed's method (Singularities::abel): what these tests check
/// is the Abel differential's quantization, zeros and refinement.
QuadMeshOptions abel_options() {
  QuadMeshOptions options;
  options.singularities = Singularities::abel;
  return options;
}

/// Valence (number of quads) of every quad-mesh point.
std::vector<int> quads_at(const LatticeQuads& q) {
  std::vector<int> count(q.points.size(), 0);
  for (const auto& quad : q.quads)
    for (int v : quad) ++count[static_cast<std::size_t>(v)];
  return count;
}

/// What every result must satisfy (issue 4, item 9), checked on one input.
void check_result(const TriangleSoup& input, const QuadMeshResult& r, int chi, int loops) {
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), &input);
  CHECK(q.quads == r.quads.quads.size());
  CHECK(q.triangles == 0);
  CHECK(q.inverted == 0);
  CHECK(q.flipped == 0);
  CHECK(q.manifold);
  CHECK(q.consistently_oriented);
  CHECK(q.euler_characteristic == chi);
  CHECK(q.boundary_loops == loops);
  const AcceptanceCriteria criteria;
  CHECK(q.min_scaled_jacobian >= criteria.min_scaled_jacobian);
  CHECK(q.angle_dev_mean <= criteria.max_mean_angle_deviation_deg);
  CHECK(r.extraction.incomplete_cells == 0);
  CHECK(r.extraction.bad_triangles == 0);
  CHECK(r.stray_boundary_points == 0);
  // interior irregular vertices are exactly the interior zeros, of valence 4 (m + 1)
  std::size_t interior_zeros = 0;
  for (const ZeroVertex& z : r.zero_vertices) interior_zeros += !z.on_boundary && !z.corner;
  CHECK(q.irregular_interior == interior_zeros);
  const std::vector<int> valence = quads_at(r.quads);
  for (std::size_t v = 0; v < r.quads.points.size(); ++v) {
    const SurfaceLocation& loc = r.quads.locations[v];
    if (r.boundary_loop_of_point[v] >= 0 || valence[v] == 4) continue;
    bool at_zero = false;
    for (const ZeroVertex& z : r.zero_vertices)
      if (!z.on_boundary && loc.kind == SurfaceLocation::Kind::vertex && loc.a == z.vertex) {
        at_zero = true;
        CHECK(valence[v] == 4 * (z.order + 1));
      }
    CHECK(at_zero);
  }
}

}  // namespace

TEST_CASE("the quads and their quality are the same bit for bit on one worker thread and on two") {
  // issue 21: the loops that run on both cores (closest points per sample, per
  // quad, per vertex) write one slot per index and reduce in index order
  const TriangleSoup input = analysed(test::example("plate-two-holes.geo"));
  auto run = [&](std::size_t threads) {
    const ThreadLimit limit(threads);
    CHECK(worker_threads() == threads);
    QuadMeshResult r = mesh_quads(input, QuadMeshOptions{});  // the default: auto, the cone route here
    const QuadQuality q = quad_quality(polygon_mesh(r.quads), &input);
    return std::make_pair(std::move(r), q);
  };
  const auto [one, one_quality] = run(1);
  const auto [two, two_quality] = run(2);
  REQUIRE(one.quads.quads.size() > 0);
  CHECK(one.quads.quads == two.quads.quads);
  REQUIRE(one.quads.points.size() == two.quads.points.size());
  std::size_t moved = 0;
  for (std::size_t v = 0; v < one.quads.points.size(); ++v) moved += one.quads.points[v] != two.quads.points[v];
  CHECK(moved == 0);
  CHECK(one_quality.hausdorff_rel == two_quality.hausdorff_rel);
  CHECK(one_quality.min_scaled_jacobian == two_quality.min_scaled_jacobian);
  CHECK(one_quality.angle_dev_mean == two_quality.angle_dev_mean);
}

TEST_CASE("a cone route kept first computes no forms and chooses none; the Abel route does both") {
  // the forms (bunny-open: 1.8 s) and the search for the most uniform one (0.4 s)
  // are only the Abel route's
  const TriangleSoup input = analysed(test::example("plate-two-holes.geo"));
  const auto has_stage = [](const QuadMeshResult& r, const char* name) {
    return std::any_of(r.timings.begin(), r.timings.end(), [&](const auto& t) { return t.first == name; });
  };
  const QuadMeshResult cones = mesh_quads(input, QuadMeshOptions{});
  CHECK(cones.singularities == "cones");
  CHECK(std::isnan(cones.abel_size_band_share));  // the Abel route did not run
  CHECK(!has_stage(cones, "forms"));
  CHECK(!has_stage(cones, "form_choice"));
  CHECK(cones.coefficients.size() == 0);
  CHECK(std::isnan(cones.residuals.hodge_star_squared));
  CHECK(cones.doubled_genus == 1 - topology_of(input).euler_characteristic);  // 2g + b - 1, with boundary
  const QuadMeshResult abel = mesh_quads(input, abel_options());
  CHECK(abel.singularities == "abel");
  CHECK(has_stage(abel, "forms"));
  CHECK(has_stage(abel, "form_choice"));
  CHECK(abel.coefficients.size() == abel.doubled_genus);
  CHECK(abel.residuals.hodge_star_squared < 0.1);
  CHECK(abel.doubled_genus == cones.doubled_genus);
}

TEST_CASE("singularities auto on an annulus: the Abel quads are in the size band, so auto gives exactly them") {
  // quad size grows like r from the inner circle to the outer: within 2/3 to 4/3 of the mean
  const TriangleSoup soup = test::annulus(1.0, 2.0, 24, 192);
  QuadMeshOptions options = abel_options();
  options.size = 0.12;
  const QuadMeshResult abel = mesh_quads(soup, options);
  options.singularities = Singularities::automatic;
  const QuadMeshResult automatic = mesh_quads(soup, options);
  CHECK(automatic.singularities == "abel");
  CHECK(automatic.cones.empty());
  CHECK(automatic.abel_size_band_share >= 0.9);
  CHECK(automatic.cone_route_failure.empty());
  REQUIRE(automatic.quads.quads == abel.quads.quads);
  REQUIRE(automatic.quads.points.size() == abel.quads.points.size());
  for (std::size_t p = 0; p < abel.quads.points.size(); ++p) CHECK(automatic.quads.points[p] == abel.quads.points[p]);
}

TEST_CASE("singularities auto with a quad count: the size band and the cones measured against area / quads") {
  // the annulus at 400 quads: its Abel quads are in the band of that size, so auto
  // keeps them (measured against the default size, 1/60 of the diagonal, they were
  // not, and the cone route made 1078 quads)
  const TriangleSoup ring = test::annulus(1.0, 2.0, 12, 96);
  QuadMeshOptions options = abel_options();
  options.quads = 400;
  options.singularities = Singularities::automatic;
  const QuadMeshResult r = mesh_quads(ring, options);
  CHECK(r.singularities == "abel");
  CHECK(std::abs(static_cast<double>(r.quads.quads.size()) - 400.0) <= 0.15 * 400);
  // a long L-arm's corners take the cone route: its quads also number about 500
  // (they were 1.4 x as many on the plate with two holes)
  io::ReadOptions read;
  read.quad_size = 2.0;
  const TriangleSoup arm = io::read_surface(test::example("l-plate-long-arm.geo"), read).soup;
  options.quads = 500;
  const QuadMeshResult cones = mesh_quads(arm, options);
  CHECK(cones.singularities == "cones");
  CHECK(std::abs(static_cast<double>(cones.quads.quads.size()) - 500.0) <= 0.15 * 500);
}

TEST_CASE("annulus: a singularity-free grid, integer periods, boundaries on integer levels") {
  const TriangleSoup soup = test::annulus(1.0, 2.0, 12, 96);
  QuadMeshOptions options = abel_options();
  options.quads = 400;
  const QuadMeshResult r = mesh_quads(soup, options);
  CHECK(r.zero_vertices.empty());
  check_result(soup, r, 0, 2);
  // within 15% of the quads asked for
  CHECK(std::abs(static_cast<double>(r.quads.quads.size()) - 400.0) <= 0.15 * 400);
  for (const LoopPeriod& p : r.quantization.periods) {
    CHECK(distance_to_integer(p.after.real()) < 1e-9);
    CHECK(distance_to_integer(p.after.imag()) < 1e-9);
  }
  // V is an integer at every boundary corner of the parameterization
  const SurfaceAdjacency adjacency = surface_adjacency(r.surface);
  double worst = 0;
  for (std::size_t f = 0; f < r.surface.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i)
      if (adjacency.boundary_vertex[static_cast<std::size_t>(r.surface.triangles[f][i])])
        worst = std::max(worst, distance_to_integer(r.quantization.param.corners[f][i].imag()));
  CHECK(worst < 1e-9);
  // every quad vertex on the boundary lies on an input boundary edge (a chord of
  // the circle, 96 sides) or vertex
  const double sag = 1 - std::cos(M_PI / 96);
  for (std::size_t v = 0; v < r.quads.points.size(); ++v)
    if (r.boundary_loop_of_point[v] >= 0) {
      const double radius = r.quads.points[v].norm();
      const double circle = radius < 1.5 ? 1.0 : 2.0;
      CHECK(radius <= circle + 1e-12);
      CHECK(radius >= circle * (1 - sag) - 1e-12);
    }
}

TEST_CASE("plate with two holes (CAD): one interior zero, corners on the lattice" *
          doctest::test_suite("slow")) {
  const TriangleSoup input = analysed(test::example("plate-two-holes.geo"));
  const QuadMeshResult r = mesh_quads(input, abel_options());
  check_result(input, r, -1, 3);
  CHECK(r.quantization.corners == 4);
  CHECK(r.quantization.lattice_zeros == r.zero_vertices.size() - 4);
  // zero orders add up to -2 chi on the double
  CHECK(r.zeros.doubled_order_sum == 2);
  CHECK(r.quantization.distortion < 0.01);
  // the scale moved by 3% at most, to where the periods round no worse than at the
  // requested size (rounding_scale.h)
  CHECK(std::abs(std::sqrt(r.base_density) - 1) <= 0.03 + 1e-9);
  std::vector<double> periods;  // of h, unscaled
  for (const LoopPeriod& p : r.quantization.periods) {
    if (p.loop.rfind("bridge", 0) == 0) periods.push_back(p.before.imag() / r.scale);
    else periods.push_back(p.before.real() / r.scale);
  }
  CHECK(periods.size() == 4);
  CHECK(rounding_residual(periods, r.scale) <= rounding_residual(periods, r.scale / std::sqrt(r.base_density)));
}

TEST_CASE("curved shell with two holes (CAD): two boundary zeros on the small hole kept apart, no fold left" *
          doctest::test_suite("slow")) {
  const TriangleSoup input = analysed(test::example("curved-shell-holes.geo"));
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  const QuadMeshResult r = mesh_quads(input, options);
  check_result(input, r, -1, 3);
  // 7 mm apart on the small hole but within one cell of the image: merged into one
  // zero of order 2, the arc between them collapsed and quads cut across the hole
  std::size_t boundary_zeros = 0;
  for (const ZeroVertex& z : r.zero_vertices)
    if (z.on_boundary && !z.corner) {
      ++boundary_zeros;
      CHECK(z.order == 1);
    }
  CHECK(boundary_zeros == 2);
  CHECK(r.extraction.degenerate_cells == 0);
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), &input);
  CHECK(q.hausdorff_rel < AcceptanceCriteria{}.max_hausdorff_relative);
}

TEST_CASE("the cone route's quads are fitted to S as the Abel route's are, and judged after it" *
          doctest::test_suite("slow")) {
  // the curved shell keeps the cones at 1.5%: its quads carry the tolerance the Abel
  // route refines to (half the size) and the fitting measured them against it (the
  // cone route's quads had no tolerance: no fitting, and the route judged them
  // before the smoothing and fitting the written quads get)
  const TriangleSoup input = analyze_topology(io::read_surface(test::example("curved-shell-holes.geo")).soup).soup;
  const double diagonal = bounding_box_diagonal(input.points, input.triangles);
  QuadMeshOptions options;
  options.size_relative = 0.015;
  const QuadMeshResult r = mesh_quads(input, options);
  REQUIRE(r.singularities == "cones");
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), &input);
  CHECK(q.inverted + q.flipped == 0);
  CHECK(q.euler_characteristic == -1);
  CHECK(q.boundary_loops == 3);
  CHECK(r.improved);
  CHECK(r.max_deviation == doctest::Approx(0.5 * r.size * std::sqrt(r.base_density)));
  CHECK(r.fitting.deviation_before > 0);
  CHECK(r.fitting.deviation_after <= r.max_deviation);
  CHECK(q.hausdorff_rel * diagonal <= r.max_deviation);
  // improved once: a second call changes nothing
  QuadMeshResult again = r;
  std::vector<std::pair<std::string, double>> timings;
  Stages stages(timings, {});
  improve_quads(again, options, stages);
  CHECK(again.quads.points == r.quads.points);
  CHECK(timings.empty());
}

TEST_CASE("CAD plates that had gaps: branch points off the lattice, overlapping corner disks" *
          doctest::test_suite("slow")) {
  // A flat 150 x 80 plate with five holes: two interior zeros within a cell (in the
  // image) of a hole's level were made boundary zeros, but the untangled map still
  // branched where h vanishes, off the lattice: 2 cells covered twice were dropped.
  // A cylindrical panel with three holes: the map branched at a neighbour of the
  // zero (1 cell dropped, 1 singular vertex for 2 zeros). Both are mended by moving
  // the branch point onto the lattice (branch_points.h).
  // A long 200 x 60 plate with two holes: h is small at its short ends, so two
  // corners of one end were closer than two disk radii in the image; the first
  // corner's disk took the second's neighbourhood, translated by its own rounding,
  // and left folds there (4 cells dropped, Hausdorff 16%). Each disk now takes
  // only its half of the way to the nearest cone.
  const std::string dir = test::scratch_dir("mesh_branch_points");
  struct Plate {
    const char* name;
    const char* geo;
    int chi, loops;
    bool branch_point_moved;
  };
  const Plate plates[] = {
      {"five-holes", "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 150, 80};\n"
                     "Disk(2) = {20, 20, 0, 5};\nDisk(3) = {50, 60, 0, 12};\nDisk(4) = {90, 25, 0, 8};\n"
                     "Disk(5) = {125, 60, 0, 4};\nDisk(6) = {130, 15, 0, 6};\n"
                     "BooleanDifference{ Surface{1}; Delete; }{ Surface{2:6}; Delete; }\n",
       -4, 6, true},
      {"panel", "SetFactory(\"OpenCASCADE\");\nCircle(1) = {0, 0, 0, 60, -Pi/4, Pi/4};\n"
                "Extrude {0, 0, 100} { Curve{1}; }\nCylinder(10) = {0, 0, 20, 120, 0, 0, 6};\n"
                "Cylinder(11) = {0, 15, 50, 120, 0, 0, 8};\nCylinder(12) = {0, -15, 80, 120, 0, 0, 5};\n"
                "BooleanDifference{ Surface{1}; Delete; }{ Volume{10, 11, 12}; Delete; }\n",
       -2, 4, true},
      {"long-plate", "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 200, 60};\n"
                     "Disk(2) = {115.97, 20.70, 0, 6.39};\nDisk(3) = {84.93, 23.99, 0, 3.03};\n"
                     "BooleanDifference{ Surface{1}; Delete; }{ Surface{2:3}; Delete; }\n",
       -1, 3, false},
  };
  for (const Plate& plate : plates) {
    CAPTURE(plate.name);
    const TriangleSoup input = analysed(test::write_text(dir, std::string(plate.name) + ".geo", plate.geo), 0.015);
    QuadMeshOptions options = abel_options();
    options.size_relative = 0.015;
    const QuadMeshResult r = mesh_quads(input, options);
    CHECK((r.branch_points.snapped >= 1) == plate.branch_point_moved);
    CHECK(r.quantization.corners == 4);
    check_result(input, r, plate.chi, plate.loops);
    CHECK(r.extraction.degenerate_cells == 0);
    CHECK(quad_quality(polygon_mesh(r.quads), &input).hausdorff_rel < AcceptanceCriteria{}.max_hausdorff_relative);
  }
}

TEST_CASE("two boundary zeros of a hole beside a narrow part stay on distinct lattice points: no gap" *
          doctest::test_suite("slow")) {
  // p7 of scripts/plate-sweep: the hole 4.15 from the plate's edge has two boundary
  // zeros on its far side, under half a cell apart in the image. Merged into one
  // zero of order 2, the boundary arc between them collapsed, the map folded along
  // it, and the untangling split it into two branch points at one lattice U: the
  // quads left the region beside the arc uncovered (3 stray boundary points,
  // Hausdorff 1.5%)
  const std::string dir = test::scratch_dir("mesh_boundary_zero_pair");
  const TriangleSoup input = analysed(test::write_text(dir, "p7.geo", test::edge_hole_plate_geo()), 0.015);
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  const QuadMeshResult r = mesh_quads(input, options);
  check_result(input, r, -5, 7);
  CHECK(quad_quality(polygon_mesh(r.quads), &input).hausdorff_rel < AcceptanceCriteria{}.max_hausdorff_relative);
  // every boundary zero, as the final map has them, sits on a lattice point
  // (before: one of the pair at U = 18.92)
  std::size_t boundary_zeros = 0;
  for (const ZeroVertex& z : r.zero_vertices) {
    if (!z.on_boundary || z.corner) continue;
    ++boundary_zeros;
    for (std::size_t f = 0; f < r.surface.triangles.size(); ++f)
      for (int i = 0; i < 3; ++i)
        if (r.surface.triangles[f][i] == z.vertex) CHECK(distance_to_integer(r.quantization.param.corners[f][i].real()) < 1e-9);
  }
  CHECK(boundary_zeros == 6);
}

TEST_CASE("a plate whose first rounding leaves folds is rounded again at a nearby scale" *
          doctest::test_suite("slow")) {
  // A 150 x 50 plate with five holes, two of them 6.6 apart: at the scale of 1.5%
  // the untangling left folds between them and 7 cells were dropped (a gap,
  // Hausdorff 3%). The same form rounded at a few percent more or fewer quads has
  // none.
  const std::string dir = test::scratch_dir("mesh_rounding_retry");
  const TriangleSoup input = analysed(test::write_text(dir, "five-holes.geo", test::five_hole_plate_geo()), 0.015);
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  const QuadMeshResult r = mesh_quads(input, options);
  CHECK(r.rounding_attempts >= 1);
  CHECK(r.form_attempts == 1);
  check_result(input, r, -4, 6);
  CHECK(r.extraction.degenerate_cells == 0);
  CHECK(quad_quality(polygon_mesh(r.quads), &input).hausdorff_rel < 0.02);
  // within 15% of the target
  CHECK(std::abs(static_cast<double>(r.quads.quads.size()) / r.expected_quads - 1) <= 0.15);
}

TEST_CASE("pig: the folds near its cones are untangled, the extraction drops no cell" *
          doctest::test_suite("slow")) {
  const TriangleSoup input = analysed(test::shared_mesh("pig.off"));
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  options.max_deviation = -1;
  options.split_long_edges = false;  // the input's own folds
  options.smoothing = false;         // the refinement's guard alone, below
  const QuadMeshResult r = mesh_quads(input, options);
  // the quantization leaves folds a few rings from the zeros and corners (27 on
  // this input), which moving one vertex at a time could not undo
  CHECK(r.quantization.flipped > 0);
  CHECK(r.untangle.flipped_after == 0);
  CHECK(r.extraction.bad_triangles == 0);
  CHECK(r.extraction.incomplete_cells == 0);
  CHECK(r.extraction.degenerate_cells == 0);
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), &input);
  CHECK(q.inverted == 0);
  CHECK(q.euler_characteristic == -5);
  CHECK(q.boundary_loops == 7);

  // chord refinement keeps the worst quad as good as it was (0.079 here): without
  // the guard a round split two thin quads beside the snout (0.030). The round
  // the guard undoes is tried again one chord at a time, and a chord that fails
  // alone is left out: the others are still split
  options.max_deviation = 0;
  const QuadMeshResult refined = mesh_quads(input, options);
  CHECK(refined.refinement.rounds_undone > 0);
  CHECK(refined.refinement.chords_split > 0);
  const QuadQuality qr = quad_quality(polygon_mesh(refined.quads), nullptr);
  CHECK(qr.min_scaled_jacobian >= std::min(q.min_scaled_jacobian, AcceptanceCriteria{}.min_scaled_jacobian));
}

TEST_CASE("flatmesh: triangles wider than the quads are split, and the better of the two meshes kept" *
          doctest::test_suite("slow")) {
  // its longest edges are 3 quads long (0.1 to 1.16 around a size of 0.38): one
  // linear map per triangle across several quads, mean angle deviation 5.28 degrees
  // as the extraction leaves it (no smoothing), 4.84 on the split triangulation
  const TriangleSoup input = analysed(test::shared_mesh("flatmesh.off"));
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  options.smoothing = false;
  const QuadMeshResult r = mesh_quads(input, options);
  CHECK(r.long_edges_split > 0);
  CHECK(r.long_edges_kept);
  CHECK(r.surface.points.size() > input.points.size());
  check_result(input, r, -3, 5);
  CHECK(r.timings.front().first == "other_triangulation");
  // the angle smoothing takes the input's own triangulation under 5 degrees too
  // (5.20 -> 4.72), and either result meets every criterion
  options.smoothing = true;
  const QuadMeshResult smoothed = mesh_quads(input, options);
  CHECK(smoothed.long_edges_split > 0);
  check_result(input, smoothed, -3, 5);
  CHECK(smoothed.angle_smoothing.angle_dev_after < smoothed.angle_smoothing.angle_dev_before);
}

TEST_CASE("kitten with two holes: genus 1, two zeros of order 1" * doctest::test_suite("slow")) {
  const TriangleSoup input = analysed(test::shared_mesh("kitten-2holes.obj"));
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  const QuadMeshResult r = mesh_quads(input, options);
  check_result(input, r, -2, 2);
  CHECK(r.zeros.doubled_order_sum == 4);
}

TEST_CASE("fertility: corners moved onto its extremities bring the quads within 1% of the diagonal" *
          doctest::test_suite("slow")) {
  const TriangleSoup input = analysed(test::shared_mesh("fertility-3holes.obj"));
  const double diagonal = bounding_box_diagonal(input.points, input.triangles);
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  const QuadMeshResult r = mesh_quads(input, options);
  check_result(input, r, -9, 3);
  // after the chord refinement, 1.4% of the diagonal where the quads are 3 times the size
  CHECK(r.fitting.deviation_before > 0.01 * diagonal);
  CHECK(r.fitting.moved_points > 0);
  CHECK(r.fitting.deviation_after < 0.6 * r.fitting.deviation_before);
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), &input);
  CHECK(q.hausdorff_rel < AcceptanceCriteria{}.max_hausdorff_relative);
}

TEST_CASE("aqua-center: splitting chords brings the quads within the tolerance, singular vertices unchanged" *
          doctest::test_suite("slow")) {
  const TriangleSoup input = analysed(test::shared_mesh("aqua-center.off"));
  const double diagonal = bounding_box_diagonal(input.points, input.triangles);
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  options.max_deviation = -1;  // off
  const QuadMeshResult plain = mesh_quads(input, options);
  check_result(input, plain, -1, 3);
  const QuadQuality q0 = quad_quality(polygon_mesh(plain.quads), &input);
  // the conformal size: near the rounded ends of the roof the quads are several
  // times the requested size and cut across the surface
  CHECK(q0.hausdorff_rel > 0.02);
  CHECK(plain.refinement.chords_split == 0);

  options.max_deviation = 0;  // default: half the size
  const QuadMeshResult r = mesh_quads(input, options);
  check_result(input, r, -1, 3);
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), &input);
  // half the target size (r.size is the base lattice's, coarser by 1 / sqrt(base_density))
  CHECK(r.max_deviation == doctest::Approx(0.5 * r.size * std::sqrt(r.base_density)));
  CHECK(r.refinement.chords_split > 0);
  CHECK(r.refinement.tolerance_met);
  CHECK(r.refinement.deviation_after <= r.max_deviation);
  // the estimate agrees with the quality module's two-sided Hausdorff distance
  CHECK(q.hausdorff_rel * diagonal == doctest::Approx(r.refinement.deviation_after).epsilon(0.1));
  CHECK(q.hausdorff_rel < AcceptanceCriteria{}.max_hausdorff_relative);
  // the quad count stays within 15% of the target
  CHECK(std::abs(static_cast<double>(q.quads) - r.expected_quads) <= 0.15 * r.expected_quads);
  CHECK(q.irregular_interior == q0.irregular_interior);
}

TEST_CASE("bunny at 1.5%: smoothing the worst quads lifts the minimum scaled Jacobian over 0.3" *
          doctest::test_suite("slow")) {
  // a boundary quad at a hole rim that zigzags in the scan, and quads beside it
  const TriangleSoup input = analysed(test::shared_mesh("bunny-open.obj"));
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.015;
  const QuadMeshResult r = mesh_quads(input, options);
  CHECK(r.smoothing.min_before < AcceptanceCriteria{}.min_scaled_jacobian);
  CHECK(r.smoothing.min_after >= AcceptanceCriteria{}.min_scaled_jacobian);
  CHECK(r.smoothing.moved_points > 0);
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), nullptr);
  CHECK(q.min_scaled_jacobian >= AcceptanceCriteria{}.min_scaled_jacobian);
  // the fitting and the angle smoothing after it keep their quads' figure at
  // min(before, 0.35 and 0.5): the smoothing's minimum (below 0.35) holds to the
  // end, and Verdict's figure is at least the one the pipeline holds the quads to
  const std::vector<double> sound = sound_scaled_jacobians(polygon_mesh(r.quads));
  CHECK(*std::min_element(sound.begin(), sound.end()) >= std::min(r.smoothing.min_after, 0.35) - 1e-12);
  CHECK(q.min_scaled_jacobian >= *std::min_element(sound.begin(), sound.end()));
  CHECK(q.inverted == 0);
  CHECK(q.euler_characteristic == -3);
  CHECK(q.boundary_loops == 5);
}

TEST_CASE("chord refinement never turns a quad over: a round that would is undone" *
          doctest::test_suite("slow")) {
  // bunny-open at 2%: splitting the chords through its ears places a quad centre
  // where the split quads would lose shape or turn over (at 2%, before the scale was
  // chosen for its rounding, 1 inverted quad without the guard); that split is
  // undone and others go ahead (this was 2.5% until close boundary zeros of one
  // loop were kept apart, which changed the bunny's rounding)
  const TriangleSoup input = analysed(test::shared_mesh("bunny-open.obj"));
  QuadMeshOptions options = abel_options();
  options.size_relative = 0.02;
  const QuadMeshResult r = mesh_quads(input, options);
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), nullptr);
  CHECK(q.inverted == 0);
  CHECK(r.refinement.rounds_undone >= 1);
  CHECK(r.refinement.chords_split > 0);
  CHECK(q.euler_characteristic == -3);
  CHECK(q.boundary_loops == 5);
}

TEST_CASE("--form, --coeffs and --rotate choose the differential") {
  const TriangleSoup soup = test::annulus(1.0, 2.0, 8, 64);
  QuadMeshOptions plain = abel_options();
  plain.quads = 200;
  QuadMeshOptions rotated = plain;
  rotated.rotate = true;
  const QuadMeshResult a = mesh_quads(soup, plain), b = mesh_quads(soup, rotated);
  // i h: the parameterization turned by a quarter, the same quads
  CHECK(b.quads.quads.size() == a.quads.quads.size());
  const Complex za = a.quantization.param.corners[0][0], zb = b.quantization.param.corners[0][0];
  CHECK(std::abs(zb - Complex(0, 1) * za) < 1e-12);
  QuadMeshOptions first = plain;
  first.form = 0;
  QuadMeshOptions coeffs = plain;
  coeffs.coefficients = {2.0};
  CHECK(mesh_quads(soup, first).coefficients[0] == doctest::Approx(1.0));
  CHECK(mesh_quads(soup, coeffs).quads.quads.size() == a.quads.quads.size());
  QuadMeshOptions wrong = abel_options();
  wrong.coefficients = {1.0, 2.0};
  CHECK_THROWS_AS(mesh_quads(soup, wrong), Error);
  QuadMeshOptions bad_form = abel_options();
  bad_form.form = 3;
  CHECK_THROWS_AS(mesh_quads(soup, bad_form), Error);
}

TEST_CASE("boundary levels: least-squares rounding that keeps levels apart and in order") {
  // bunny-open's levels: two ear holes 0.4 apart must not share a level
  const std::vector<double> levels{0.0, -47.395, -1.908, -0.048, -2.313};
  const std::vector<double> rounded = round_levels(levels);
  CHECK(rounded == std::vector<double>{0.0, -47.0, -2.0, 0.0, -3.0});
  // levels 1/4 apart or closer may share one; a lone level keeps its rounding
  CHECK(round_levels({0.0, 0.2, 3.6}) == std::vector<double>{0.0, 0.0, 4.0});
  // three levels in 0.8 need three integers, nearest in the least-squares sense
  CHECK(round_levels({0.0, 0.4, 0.8}) == std::vector<double>{0.0, 1.0, 2.0});
  CHECK(round_nonzero(0.3) == 1.0);
  CHECK(round_nonzero(-0.3) == -1.0);
  CHECK(round_nonzero(0.2) == 0.0);
  CHECK(round_nonzero(2.49) == 2.0);
}

TEST_CASE("--form auto's objective on the annulus: the variance of log|h|^2 of -i dz/z") {
  // |h| ~ 1/r on 1 <= r <= 2, so log|h|^2 = c - 2 log r; with the area weight r dr:
  // Var(log r) = E[log^2 r] - E[log r]^2 = 0.216408 - 0.424196^2 = 0.036466, times 4
  TriangleSoup soup = test::annulus(1.0, 2.0, 24, 192);
  split_boundary_chords(soup);
  const SymmetricForms forms = compute_symmetric_forms(to_surface_mesh(soup));
  const std::vector<FaceMap> basis = symmetric_face_maps(forms, soup);
  REQUIRE(basis.size() == 1);
  CHECK(uniformity_ratio(soup, basis, Eigen::VectorXd::Ones(1)) == doctest::Approx(4 * 0.036466).epsilon(0.02));
  // scale invariant, and the optimum of a one-dimensional space is its unit vector
  CHECK(uniformity_ratio(soup, basis, -3.0 * Eigen::VectorXd::Ones(1)) ==
        doctest::Approx(uniformity_ratio(soup, basis, Eigen::VectorXd::Ones(1))));
  CHECK(std::abs(most_uniform_combination(soup, basis)[0]) == doctest::Approx(1.0));
}
