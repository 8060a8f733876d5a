#include "io/atomic_file.h"
#include "io/deck_element.h"
#include "io/file_format.h"
#include "io/write_mesh.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/size_band.h"
#include "tools/common/exit_codes.h"
#include "tools/common/input_surface.h"
#include "tools/common/output_paths.h"
#include "tools/common/usage_error.h"
#include "tools/quadmesh/commands.h"
#include "tools/quadmesh/mesh_steps.h"
#include "tools/quadmesh/quad_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace qm::tools {

namespace {
int nodes_per_quad(const MeshOptions& options) { return options.order == 1 ? 4 : options.complete ? 9 : 8; }
}  // namespace

void check_mesh_files(const MeshOptions& options) {
  if (options.skip_unsupported && !options.each_component)
    throw UsageError("--skip-unsupported applies to --each-component (the parts of an assembly)");
  if (options.each_component && options.order != 1)
    throw UsageError("--order 2 is not written with --each-component yet: mesh the parts one by one for quadratic "
                     "quads");
  check_output_file({"-o", options.output});
  check_output_file({"--report", options.report});
  check_distinct({{"the input", options.input}, {"-o", options.output}, {"--report", options.report}});
  if (!options.coefficients.empty() &&
      std::all_of(options.coefficients.begin(), options.coefficients.end(), [](double c) { return c == 0; }))
    throw UsageError("--coeffs: all coefficients are 0, so h would be 0; give at least one that is not");
  if (options.order != 1 && options.order != 2)
    throw UsageError(fmt::format("--order {}: quadmesh writes linear (--order 1) or quadratic (--order 2) quads",
                                 options.order));
  if (options.complete && options.order != 2)
    throw UsageError("--complete asks for 9-node quads: it needs --order 2");
  try {
    io::check_element_request(options.output, nodes_per_quad(options), options.element_type);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  if (options.quads > options.max_quads)
    throw UsageError(fmt::format("--quads {} is more than --max-quads {}; raise --max-quads to mesh it",
                                 options.quads, options.max_quads));
}

/// The largest --size taken, as a share of the model's bounding-box diagonal: a
/// surface with holes needs quads well below half its extent.
constexpr double max_size_share_of_diagonal = 0.5;

void check_quad_estimate(const MeshOptions& options, const TriangleSoup& soup) {
  if (options.quads > 0) return;  // checked with the files
  QuadMeshOptions asked_for;
  asked_for.size = options.size;
  asked_for.size_relative = options.size_relative;
  const std::string asked = options.size > 0            ? fmt::format("--size {:g}", options.size)
                            : options.size_relative > 0 ? fmt::format("--size {:g}%", 100 * options.size_relative)
                                                        : std::string("the default size (1/60 of the diagonal)");
  // a length in other units than the model's (--size 1.5 meant as 1.5%, or mm
  // for a model in metres) would have the whole pipeline run for minutes on a
  // lattice of a cell or two and fail
  const double diagonal = bounding_box_diagonal(soup.points, soup.triangles);
  const double size = options.size > 0 ? options.size : options.size_relative * diagonal;
  if (diagonal > 0 && size > max_size_share_of_diagonal * diagonal)
    throw UsageError(fmt::format("{} is {:.3g} times the model's bounding-box diagonal ({:g}): give a length "
                                 "below {:g}, or a share of the diagonal such as --size 1.5%",
                                 asked, size / diagonal, diagonal, max_size_share_of_diagonal * diagonal));
  const double estimate = implied_quad_count(soup, asked_for);
  if (!(estimate > static_cast<double>(options.max_quads))) return;
  throw UsageError(fmt::format("{} implies about {:.3g} quads (surface area / size^2), more than --max-quads {}; "
                               "give a larger --size, or raise --max-quads to mesh it",
                               asked, std::min(estimate, 1e300), options.max_quads));
}

void check_cad_quad_estimate(const MeshOptions& options, const io::ReadOptions& read) {
  if (!io::is_cad(io::format_of(options.input)) || (options.size <= 0 && options.size_relative <= 0)) return;
  io::ReadOptions coarse = read;
  coarse.cad_mesh_size = 0;
  coarse.quad_size = 0;
  coarse.quad_size_relative = 0.1;
  check_quad_estimate(options, io::read_surface(options.input, coarse).soup);
}

namespace {

/// --form K must name one of the surface's symmetric forms (the doubled surface's
/// genus of them), said as the command line counts them, from 1; --coeffs must
/// give one value per form. Told before the forms are computed.
void check_form_choice(const MeshOptions& options, const AnalyzedSurface& surface) {
  const Applicability verdict = assess_applicability(surface);
  const int forms = verdict.doubled_genus;  // with boundary; closed surfaces are not meshed yet (exit 4)
  if (verdict.kind == SurfaceCase::closed || forms <= 0) return;
  if (!options.coefficients.empty() && static_cast<int>(options.coefficients.size()) != forms)
    throw Error(ErrorCode::bad_input, fmt::format("--coeffs has {} values but the surface has {} symmetric forms",
                                                  options.coefficients.size(), forms));
  if (options.form >= forms)
    throw Error(ErrorCode::bad_input, fmt::format("--form {}: the surface has {} symmetric forms (1 to {})",
                                                  options.form + 1, forms, forms));
}

/// The mesh and the report appear together or not at all; a file that cannot
/// be written is an output path problem (exit 2), and then none is left.
void write_outputs(const MeshOptions& options, const QuadMeshResult& result, const MeshSummary& summary,
                   const QuadraticQuads* quadratic) {
  try {
    io::AtomicFiles files;
    io::WriteOptions write;
    write.msh_version = options.msh_version;
    write.element_type = options.element_type;
    files.add(options.output, [&](const std::string& temporary) {
      io::write_mesh(temporary, output_mesh(result, quadratic), write);
    });
    if (!options.report.empty())
      files.add(options.report, [&](const std::string& temporary) { write_report(temporary, summary); });
    files.commit();
  } catch (const Error& e) {
    throw UsageError(fmt::format("{}; no output was written", e.what()));
  }
}

/// "<lead> near (x, y, z)": the centroid of the first triangle where the extraction
/// failed, or "" when there is none.
std::string near_first_problem(const QuadMeshResult& r, const std::string& lead) {
  if (r.extraction.first_problem_triangle < 0) return "";
  const Triangle& t = r.surface.triangles[static_cast<std::size_t>(r.extraction.first_problem_triangle)];
  const Vec3 c = (r.surface.points[static_cast<std::size_t>(t[0])] + r.surface.points[static_cast<std::size_t>(t[1])] +
                  r.surface.points[static_cast<std::size_t>(t[2])]) / 3.0;
  return fmt::format("{} near ({:.6g}, {:.6g}, {:.6g})", lead, c.x(), c.y(), c.z());
}

/// The longest quad edge, and its midpoint, among the quads whose centroid lies
/// within `reach` plus their own longest edge of `near` (reach infinite: all).
struct LongestEdge {
  double length = 0;
  Vec3 at = Vec3::Zero();
};
LongestEdge longest_quad_edge(const LatticeQuads& quads, const Vec3& near, double reach) {
  LongestEdge longest;
  for (const auto& quad : quads.quads) {
    Vec3 centroid = Vec3::Zero();
    LongestEdge own;
    for (std::size_t k = 0; k < 4; ++k) {
      const Vec3& a = quads.points[static_cast<std::size_t>(quad[k])];
      const Vec3& b = quads.points[static_cast<std::size_t>(quad[(k + 1) % 4])];
      centroid += a / 4.0;
      if ((a - b).norm() > own.length) own = {(a - b).norm(), (a + b) / 2};
    }
    if (own.length > longest.length && (centroid - near).norm() <= own.length + reach) longest = own;
  }
  return longest;
}

/// Whether quads of quality `q` conform to an input of Euler characteristic `chi`
/// with `loops` boundary loops: its topology, manifold, consistently oriented,
/// quads only.
bool conforms(const QuadQuality& q, int chi, int loops) {
  return q.euler_characteristic == chi && q.boundary_loops == loops && q.manifold && q.consistently_oriented &&
         q.triangles == 0 && q.other_faces == 0;
}

}  // namespace

void require_conforming(const MeshSummary& s, const QuadMeshResult& r) {
  const QuadQuality& q = s.quality;
  if (conforms(q, s.input_euler_characteristic, s.input_boundary_loops)) return;
  const std::string where = near_first_problem(r, " first");
  // the usual cause: a long end or a protrusion, where every such differential
  // decays and the cells grow until the boundary there collapses
  std::string cause;
  const LongestEdge longest =
      longest_quad_edge(r.quads, Vec3::Zero(), std::numeric_limits<double>::infinity());
  if (r.size_requested > 0 && longest.length > 4 * r.size_requested)
    cause = fmt::format("; quad edges reach {:.0f} times --size near ({:.6g}, {:.6g}, {:.6g}): the differential is "
                        "small there (a long end or a protrusion), a limit of the method (README Limits)",
                        longest.length / r.size_requested, longest.at.x(), longest.at.y(), longest.at.z());
  const std::string cones =
      r.cone_route_failure.empty() ? std::string() : "; quarter-turn cones did not help: " + r.cone_route_failure;
  throw Error(ErrorCode::solver,
              fmt::format("the quad mesh would not be conforming (chi {} and {} boundary loops, the input has {} "
                          "and {}): {} folded triangles and {} incomplete cells are left{}{}{}; no output was written; "
                          "try another --size or --form",
                          q.euler_characteristic, q.boundary_loops, s.input_euler_characteristic,
                          s.input_boundary_loops, r.extraction.bad_triangles, r.extraction.incomplete_cells, where,
                          cause, cones));
}

namespace {

/// A curved quad whose Jacobian determinant is <= 0 somewhere is rejected by every
/// solver: refuse to write the mesh (exit 1), naming where the worst is.
void require_positive_jacobians(const MeshSummary& s, const QuadraticQuads* quadratic) {
  if (!s.curved || s.curved->non_positive == 0) return;
  Vec3 c = Vec3::Zero();
  for (std::size_t i = 0; i < 4; ++i)
    c += quadratic->points[static_cast<std::size_t>(quadratic->elements[static_cast<std::size_t>(s.curved->worst)][i])] / 4.0;
  throw Error(ErrorCode::solver,
              fmt::format("{} curved quads would have a Jacobian determinant <= 0 (min ratio {:.3g}, near ({:.6g}, "
                          "{:.6g}, {:.6g})): the surface bends too much within a quad; no output was written; give a "
                          "smaller --size",
                          s.curved->non_positive, s.curved->min_ratio, c.x(), c.y(), c.z()));
}

/// Lattice cells the extraction could not make into quads leave gaps in the mesh
/// (next to the boundary: the topology is the input's, so the mesh is written):
/// one warning line on stderr, even with --quiet, naming the first.
void warn_if_cells_dropped(const QuadMeshResult& r) {
  const std::size_t dropped = r.extraction.incomplete_cells + r.extraction.degenerate_cells;
  if (dropped == 0) return;
  const std::string where = near_first_problem(r, ", the first");
  fmt::print(stderr,
             "quadmesh: warning: {} lattice cells could not be made into quads{}: the mesh leaves a gap there; try "
             "another --size or --form\n",
             dropped, where);
}

/// Quad boundary points off S's boundary: the quads leave part of S uncovered or
/// cover part of it twice there, though the topology is the input's (so the mesh is
/// written). One warning line on stderr, even with --quiet, naming the first.
void warn_if_stray_boundary(const QuadMeshResult& r) {
  if (r.stray_boundary_points == 0) return;
  const Vec3& p = r.first_stray_point;
  fmt::print(stderr,
             "quadmesh: warning: {} points of the quads' boundary are not on the input's boundary, the first near "
             "({:.6g}, {:.6g}, {:.6g}): the quads leave a gap or overlap there; try another --size or --form\n",
             r.stray_boundary_points, p.x(), p.y(), p.z());
}

/// Inverted quads are written (the mesh is conforming) but a solver rejects them:
/// one warning line on stderr, even with --quiet, naming the first.
void warn_if_inverted(const MeshSummary& s, const QuadMeshResult& r) {
  if (s.quality.inverted + s.quality.flipped == 0) return;
  const std::vector<double> jacobians = sound_scaled_jacobians(polygon_mesh(r.quads));
  const auto first = std::find_if(jacobians.begin(), jacobians.end(), [](double j) { return j <= 0; });
  if (first == jacobians.end()) return;
  Vec3 c = Vec3::Zero();
  for (int v : r.quads.quads[static_cast<std::size_t>(first - jacobians.begin())])
    c += r.quads.points[static_cast<std::size_t>(v)] / 4.0;
  fmt::print(stderr,
             "quadmesh: warning: {} inverted quads and {} turned over against their neighbours (min Verdict "
             "scaled Jacobian {:.3g}), the first near ({:.6g}, {:.6g}, {:.6g}); a solver will reject them: try "
             "another --size or --form\n",
             s.quality.inverted, s.quality.flipped, s.quality.min_scaled_jacobian, c.x(), c.y(), c.z());
}

/// Quads farther from the input than the refinement's tolerance: where the form is
/// small (a protrusion, a long end) its quads are larger than the size asked, and
/// the chords the budget allows did not bring them close. One warning line, even
/// with --quiet, naming the farthest place (quality module: two-sided Hausdorff).
void warn_if_far(const MeshSummary& s, const QuadMeshResult& r, double diagonal) {
  const double distance = s.quality.hausdorff_rel * diagonal;
  if (r.max_deviation <= 0 || !(distance > 1.25 * r.max_deviation)) return;
  const Vec3& p = s.quality.hausdorff_at;
  // the longest edge of the quads around that place, against the size asked
  const double longest = longest_quad_edge(r.quads, p, distance).length;
  const double ratio = r.size_requested > 0 ? longest / r.size_requested : 0;
  const bool gap = r.extraction.incomplete_cells + r.extraction.degenerate_cells > 0;
  const bool cones = r.singularities == "cones";
  const std::string cause =
      gap ? "the gap above, or quads larger than --size there"
      : ratio >= 1.5
          ? fmt::format("the quads there are up to {:.0f} times --size: {}", ratio,
                        cones ? "the cones leave the quads large there (too few of them for a protrusion or a narrow end)"
                              : "the differential is small there (a protrusion, a long end or a narrow part)")
          : "the surface is curved there at the scale of --size";
  // the cones kept for being nearer than the Abel quads (cone_route.h keep_nearer_cones)
  const std::string kept = cones && std::isfinite(r.abel_distance_relative)
                               ? fmt::format(" (the cones' quads are kept: the Abel quads are {:.2g}% of the diagonal "
                                             "from it)",
                                             100 * r.abel_distance_relative)
                               : std::string();
  fmt::print(stderr,
             "quadmesh: warning: the quads are up to {:.3g} ({:.2g}% of the diagonal) from the surface, near ({:.6g}, "
             "{:.6g}, {:.6g}), against {:.3g} asked (--max-deviation){}: {}; try another --form or a smaller --size\n",
             distance, 100 * s.quality.hausdorff_rel, p.x(), p.y(), p.z(), r.max_deviation, kept, cause);
}
}  // namespace

io::ReadOptions mesh_read_options(const MeshOptions& options, const CommonOptions& common) {
  io::ReadOptions read;
  read.cad_mesh_size = common.cad_mesh_size;
  read.quad_size = options.size;
  read.quad_size_relative = options.size_relative;
  return read;
}

QuadMeshOptions quad_mesh_options(const MeshOptions& options) {
  QuadMeshOptions mesher;
  mesher.form = options.form;
  mesher.coefficients = options.coefficients;
  mesher.rotate = options.rotate;
  mesher.singularities = options.singularities == "auto" ? Singularities::automatic : Singularities::abel;
  mesher.cone_placement =
      options.cone_placement == "cross-field" ? ConePlacement::cross_field : ConePlacement::greedy;
  mesher.smoothing = !options.no_smoothing;
  mesher.coarsen = !options.no_coarsening;
  mesher.size = options.size;
  mesher.size_relative = options.size_relative;
  mesher.quads = options.quads;
  mesher.max_quads = options.max_quads;
  mesher.corner_angle_deg = options.corner_angle_deg;
  mesher.tip_angle_deg = options.tip_angle_deg;
  mesher.max_deviation = options.max_deviation;
  mesher.max_deviation_relative = options.max_deviation_relative;
  return mesher;
}

namespace {

/// What the Abel quads miss that sends auto to the cones (cone_route.h): the size
/// band (the share within it, and the largest quad when above size_ratio_limit),
/// the corners' quad counts, or both.
std::string abel_shortfall(const QuadQuality& q, double band_share) {
  std::string band = fmt::format("{:.0f}% of them within [0.5, 2] x --size", 100 * band_share);
  if (q.size_ratio_max > size_ratio_limit) band += fmt::format(", the largest {:.1f} x", q.size_ratio_max);
  if (corners_wrong(q) == 0) return "miss the size band (" + band + ")";
  return fmt::format("put {} of the input's {} corners in the wrong number of quads ({})", corners_wrong(q),
                     corners_total(q), band);
}

}  // namespace

void warn_about_result(const MeshSummary& summary, const QuadMeshResult& result, double diagonal) {
  warn_if_cells_dropped(result);
  // (Abel quads whose chords through the quads above the band were split are in
  // the band then: split_abel_quads_above_band keeps only that)
  const bool split_into_band = result.singularities == "abel" && result.size_refinement.chords_split > 0;
  if (!result.cone_route_failure.empty() && !(split_into_band && corners_wrong(summary.quality) == 0))
    fmt::print(stderr, "quadmesh: warning: the Abel quads {}; quarter-turn cones did not help: {}; the Abel result "
                       "is kept\n",
               abel_shortfall(summary.quality, result.abel_size_band_share), result.cone_route_failure);
  warn_if_stray_boundary(result);
  warn_if_inverted(summary, result);
  warn_if_far(summary, result, diagonal);
}

namespace {

/// Gmsh's triangle sizes tried, as fractions of the quad size, in this order, when
/// its first triangulation of a CAD part (0.75 x the quad size by default) gives
/// quads that miss what the triangles decide: where cones crowd a narrow part,
/// whether a map folds depends on the triangles under it (the T-plate at 2%: folds
/// at 0.75 and 0.6, sound at 0.45; the rod end at 3%: sound at 0.6; a channel at
/// 1.5%, two bolt holes 0.95 quads apart: every cone map folds across them at 0.75,
/// the Abel quads kept with an inverted one; at 0.6, the cones' quads all in the band).
constexpr double cad_retry_mesh_sizes[] = {0.6, 0.45, 0.33};
/// Quads that conform, none inverted, but off the size band get the first of those
/// only: a finer triangulation mends the band where cones crowd a narrow part (a
/// wheel at 1.5%, 67% -> 96% on 0.6 x; a link at 2%, 69% -> 94%), not where no
/// cone map fits (two wheels at 2%, their rims under a quad: none of the three
/// better, at 25-27 x the first run's time).
constexpr std::size_t off_band_retries = 1;

/// How far quads are from what a finer triangulation can mend, worst first.
enum class TriangulationStanding { not_conforming, inverted, off_band, sound };

/// `r`'s standing against `in`: require_conforming's topology, then no inverted or
/// turned-over quad (a solver rejects them), then in the size band (in_size_band).
TriangulationStanding triangulation_standing(const QuadMeshResult& r, const InputSurface& in) {
  const PolygonMesh mesh = polygon_mesh(r.quads);
  const QuadQuality q = quad_quality(mesh, nullptr);
  if (!conforms(q, static_cast<int>(in.surface.report.euler_characteristic),
                static_cast<int>(in.surface.report.boundary_loop_count())))
    return TriangulationStanding::not_conforming;
  if (q.inverted + q.flipped > 0) return TriangulationStanding::inverted;
  if (!in_size_band(quad_size_band(mesh, r.size_requested))) return TriangulationStanding::off_band;
  return TriangulationStanding::sound;
}

/// What the warning says of quads of `standing` on Gmsh's first triangulation.
std::string shortfall(TriangulationStanding standing) {
  switch (standing) {
    case TriangulationStanding::not_conforming: return "no conforming quads";
    case TriangulationStanding::inverted: return "inverted quads";
    default: return "quads off the size band";
  }
}

/// When `result`, meshed on Gmsh's first triangulation of the CAD part (with
/// --singularities auto, whose cones are what the triangles decide; and no
/// --cad-mesh-size given), is not conforming, has inverted quads or misses the
/// size band: the part triangulated again at each of cad_retry_mesh_sizes in turn
/// (off the band only, the first off_band_retries of them) and meshed, until the
/// quads are sound (triangulation_standing); `in` and
/// `result` are then the first of those that stand best, when they stand better
/// than the first, and the returned line says so (for a warning). Otherwise they
/// stay (require_conforming then reports the first failure) and the line is empty.
/// A triangulation that fails to read, or whose topology is not the first one's,
/// is passed over.
std::string remesh_on_finer_triangulations(const MeshOptions& options, const CommonOptions& common,
                                           io::ReadOptions read, const Progress& progress, InputSurface& in,
                                           QuadMeshResult& result) {
  // the options first: the standing is for CAD parts meshed by auto only
  if (!io::is_cad(io::format_of(options.input)) || common.cad_mesh_size > 0 || options.singularities != "auto" ||
      options.form >= 0 || !options.coefficients.empty() || options.rotate || !(result.size_requested > 0))
    return {};
  const TriangulationStanding first_standing = triangulation_standing(result, in);
  TriangulationStanding best = first_standing;
  double best_fraction = 0;
  const double first = in.file.cad_mesh_size, quad_size = result.size_requested;
  std::size_t tried = 0;
  for (double fraction : cad_retry_mesh_sizes) {
    if (best == TriangulationStanding::sound ||
        (first_standing == TriangulationStanding::off_band && tried == off_band_retries))
      break;
    ++tried;
    read.cad_mesh_size = fraction * quad_size;
    progress.stage(fmt::format("{} on Gmsh's triangulation: the part triangulated again at {:g} x the quad size",
                               shortfall(first_standing), fraction));
    try {
      InputSurface again = load_input_surface(options.input, read, common.largest_component, progress);
      if (again.surface.report.euler_characteristic != in.surface.report.euler_characteristic ||
          again.surface.report.boundary_loop_count() != in.surface.report.boundary_loop_count())
        continue;
      QuadMeshResult r = mesh_quads(again.surface.soup, quad_mesh_options(options),
                                    [&](const std::string& stage) { progress.stage(stage); });
      const TriangulationStanding standing = triangulation_standing(r, again);
      if (standing <= best) continue;
      best = standing;
      best_fraction = fraction;
      in = std::move(again);
      result = std::move(r);
    } catch (const Error&) {
      continue;  // this triangulation is passed over; the first failure stands
    }
  }
  if (best_fraction == 0) return {};
  const double size = best_fraction * quad_size;
  return fmt::format("Gmsh's triangulation of the part (triangles up to {:.3g}) gave {}; these are meshed on a finer "
                     "one (triangles up to {:.3g}, {:g} x the quad size: --cad-mesh-size {:.6g})",
                     first, shortfall(first_standing), size, best_fraction, size);
}

}  // namespace

int run_mesh(const MeshOptions& options, const CommonOptions& common) {
  if (options.each_component) return run_mesh_each_component(options, common);
  check_mesh_files(options);
  const Progress progress(common.quiet);
  const io::ReadOptions read = mesh_read_options(options, common);
  check_cad_quad_estimate(options, read);
  InputSurface in = load_input_surface(options.input, read, common.largest_component, progress);
  require_supported(in.surface);
  check_form_choice(options, in.surface);
  check_quad_estimate(options, in.surface.soup);
  progress.stage(assess_applicability(in.surface).reason);

  QuadMeshResult result =
      mesh_quads(in.surface.soup, quad_mesh_options(options), [&](const std::string& stage) { progress.stage(stage); });
  const std::string remeshed = remesh_on_finer_triangulations(options, common, read, progress, in, result);

  std::optional<QuadraticQuads> quadratic;
  if (options.order == 2) {
    progress.stage(fmt::format("placing the nodes of the {}-node quads on the surface", nodes_per_quad(options)));
    quadratic = quadratic_output(result, options.complete,
                                 io::is_cad(io::format_of(options.input)) ? options.input : std::string(),
                                 in.surface.soup);
  }
  progress.stage("measuring quality");
  const MeshSummary summary = summarize(in, result, options, progress.elapsed(), quadratic ? &*quadratic : nullptr);
  require_conforming(summary, result);
  require_positive_jacobians(summary, quadratic ? &*quadratic : nullptr);
  progress.stage(fmt::format("writing {}", options.output));
  write_outputs(options, result, summary, quadratic ? &*quadratic : nullptr);
  print_summary(summary);
  if (!remeshed.empty()) fmt::print(stderr, "quadmesh: warning: {}\n", remeshed);
  warn_about_result(summary, result, bounding_box_diagonal(in.surface.soup.points, in.surface.soup.triangles));
  return exit_ok;
}

}  // namespace qm::tools
