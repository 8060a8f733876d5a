#include "tools/quadmesh/quad_output.h"

#include "io/cad_curve_points.h"
#include "libquadmesh/cones/cone_placement.h"
#include "libquadmesh/quality/size_band.h"

#include "tools/common/quality_json.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <set>

namespace qm::tools {

namespace {

using Json = nlohmann::ordered_json;

Json complex_json(Complex z) { return Json::array({z.real(), z.imag()}); }

}  // namespace

std::set<int> CurveLookup::at(const SurfaceLocation& loc) const {
  std::set<int> out;
  if (loc.kind == SurfaceLocation::Kind::edge) {
    const auto it = curve_of_edge.find({loc.a, loc.b});
    if (it != curve_of_edge.end()) out.insert(it->second);
  } else if (loc.kind == SurfaceLocation::Kind::vertex) {
    const auto [lo, hi] = curves_of_vertex.equal_range(loc.a);
    for (auto it = lo; it != hi; ++it) out.insert(it->second);
  }
  return out;
}

CurveLookup curve_lookup(const CadCurves& cad) {
  CurveLookup out;
  for (const CurveEdge& e : cad.edges) {
    out.curve_of_edge[{std::min(e.a, e.b), std::max(e.a, e.b)}] = e.curve;
    out.curves_of_vertex.insert({e.a, e.curve});
    out.curves_of_vertex.insert({e.b, e.curve});
  }
  return out;
}

QuadraticQuads quadratic_output(const QuadMeshResult& result, bool complete, const std::string& cad_path,
                                const TriangleSoup& input) {
  QuadraticQuadsOptions options;
  options.complete = complete;
  // on a working triangulation (coarsened: inscribed in the input) the nodes go onto the input itself
  const TriangleSoup& surface = result.coarsened_from > 0 ? input : result.surface;
  QuadraticQuads out = quadratic_quads(result.quads.points, result.quads.quads, surface, options);
  if (cad_path.empty() || result.surface.cad.edges.empty()) return out;
  const CurveLookup curves = curve_lookup(result.surface.cad);
  std::vector<io::CurvePointQuery> queries;
  std::vector<int> moved;
  // the corners on one CAD curve (a corner at a CAD vertex, on two, is exact already)
  for (std::size_t v = 0; v < result.quads.points.size(); ++v) {
    if (result.boundary_loop_of_point[v] < 0) continue;
    const std::set<int> on = curves.at(result.quads.locations[v]);
    if (on.size() != 1) continue;
    queries.push_back({*on.begin(), out.points[v]});
    moved.push_back(static_cast<int>(v));
  }
  for (int node : out.boundary_nodes) {
    const auto [a, b] = out.edge_of_node[static_cast<std::size_t>(node - out.first_edge_node)];
    const std::set<int> ca = curves.at(result.quads.locations[static_cast<std::size_t>(a)]);
    const std::set<int> cb = curves.at(result.quads.locations[static_cast<std::size_t>(b)]);
    for (int c : ca)
      if (cb.count(c)) {
        queries.push_back({c, out.points[static_cast<std::size_t>(node)]});
        moved.push_back(node);
        break;
      }
  }
  if (queries.empty()) return out;
  const std::vector<Vec3> on_curves = io::closest_points_on_cad_curves(cad_path, queries);
  for (std::size_t i = 0; i < moved.size(); ++i) out.points[static_cast<std::size_t>(moved[i])] = on_curves[i];
  out.cad_nodes = moved.size();
  for (std::size_t i = 0; i < moved.size(); ++i)  // the corners may have moved by the triangulation's sagitta
    if (moved[i] < out.first_edge_node)
      out.max_move = std::max(out.max_move, (on_curves[i] - result.quads.points[static_cast<std::size_t>(moved[i])]).norm());
  return out;
}

io::OutputMesh output_mesh(const QuadMeshResult& result, const QuadraticQuads* quadratic) {
  const LatticeQuads& q = result.quads;
  io::OutputMesh out;
  out.points = q.points;
  for (const auto& quad : q.quads) out.faces.push_back({quad[0], quad[1], quad[2], quad[3]});
  std::map<std::pair<int, int>, int> node_of_edge;
  if (quadratic) {
    out.points = quadratic->points;
    out.faces = quadratic->elements;
    for (std::size_t k = 0; k < quadratic->edge_of_node.size(); ++k)
      node_of_edge[{quadratic->edge_of_node[k][0], quadratic->edge_of_node[k][1]}] =
          quadratic->first_edge_node + static_cast<int>(k);
  }
  // boundary edges: used by one quad, in the quad's direction
  std::map<std::pair<int, int>, int> uses;
  for (const auto& quad : q.quads)
    for (int i = 0; i < 4; ++i) ++uses[{quad[static_cast<std::size_t>(i)], quad[static_cast<std::size_t>((i + 1) % 4)]}];
  const CadCurves& cad = result.surface.cad;
  const CurveLookup curves = curve_lookup(cad);
  std::map<int, std::string> group_of_curve;
  for (const PhysicalCurveGroup& g : cad.groups)
    for (int c : g.curves) group_of_curve[c] = g.name.empty() ? fmt::format("curve_group_{}", g.tag) : g.name;
  std::map<std::string, io::LineGroup> groups;
  std::vector<std::string> order;
  for (const auto& quad : q.quads)
    for (int i = 0; i < 4; ++i) {
      const int a = quad[static_cast<std::size_t>(i)], b = quad[static_cast<std::size_t>((i + 1) % 4)];
      if (uses.count({b, a})) continue;
      int loop = result.boundary_loop_of_point[static_cast<std::size_t>(a)];
      if (loop < 0) loop = result.boundary_loop_of_point[static_cast<std::size_t>(b)];
      std::string name = fmt::format("boundary_{}", std::max(loop, 0));
      if (!group_of_curve.empty()) {
        const std::set<int> ca = curves.at(q.locations[static_cast<std::size_t>(a)]);
        const std::set<int> cb = curves.at(q.locations[static_cast<std::size_t>(b)]);
        for (int c : ca)
          if (cb.count(c) && group_of_curve.count(c)) {
            name = group_of_curve[c];
            break;
          }
      }
      if (!groups.count(name)) {
        groups[name].name = name;
        order.push_back(name);
      }
      groups[name].edges.push_back({a, b});
      if (quadratic) groups[name].mids.push_back(node_of_edge.at({std::min(a, b), std::max(a, b)}));
    }
  std::sort(order.begin(), order.end());
  for (const std::string& name : order) out.line_groups.push_back(std::move(groups[name]));
  io::PointGroup singular{"singular_vertices", {}};
  std::vector<int> valence(q.points.size(), 0);
  for (const auto& quad : q.quads)
    for (int v : quad) ++valence[static_cast<std::size_t>(v)];
  for (std::size_t v = 0; v < q.points.size(); ++v)
    if (result.boundary_loop_of_point[v] < 0 && valence[v] != 4) singular.points.push_back(static_cast<int>(v));
  if (!singular.points.empty()) out.point_groups.push_back(std::move(singular));
  return out;
}

namespace {

/// The boundary vertices of result.surface the cone placement counts as corners
/// at its size (cone_placement.h corner_cones); none without cones.
std::set<int> corner_vertices(const QuadMeshResult& result) {
  std::set<int> out;
  if (result.cones.empty() || !(result.size > 0)) return out;
  for (const Cone& c : corner_cones(result.surface, result.size)) out.insert(c.vertex);
  return out;
}

}  // namespace

MeshSummary summarize(const InputSurface& in, const QuadMeshResult& result, const MeshOptions& options,
                      double seconds, const QuadraticQuads* quadratic) {
  MeshSummary s;
  s.input = options.input;
  const std::vector<char> on_boundary =
      result.cones.empty() ? std::vector<char>() : surface_adjacency(result.surface).boundary_vertex;
  s.quality = quad_quality(polygon_mesh(result.quads), &in.surface.soup, result.size_requested);
  for (const ZeroVertex& z : result.zero_vertices)
    if (!z.corner) (z.on_boundary ? s.expected_irregular_boundary : s.expected_irregular_interior)++;
  // the cone route: its interior cones are the irregular vertices, and its boundary
  // cones away from the corners (a straight boundary point in three quads)
  const std::set<int> corners = corner_vertices(result);
  for (const Cone& c : result.cones) {
    if (!on_boundary[static_cast<std::size_t>(c.vertex)])
      s.expected_irregular_interior += c.quads != 4;
    else if (!corners.count(c.vertex))
      ++s.expected_irregular_boundary;
  }
  s.input_euler_characteristic = static_cast<int>(in.surface.report.euler_characteristic);
  s.input_boundary_loops = in.surface.report.boundary_loop_count();
  s.seconds = seconds;

  Json j;
  j["input"] = options.input;
  j["output"] = options.output;
  j["quality"] = quality_json(s.quality);
  if (quadratic) {
    s.curved = curved_jacobians(quadratic->points, quadratic->elements);
    s.nodes_per_quad = quadratic->elements.empty() ? 4 : static_cast<int>(quadratic->elements.front().size());
    j["quality"]["min_jacobian_ratio"] = s.curved->min_ratio;
    j["quality"]["non_positive_jacobian_elements"] = s.curved->non_positive;
  }
  j["order"] = {{"order", quadratic ? 2 : 1},
                {"nodes_per_quad", s.nodes_per_quad},
                {"boundary_nodes", quadratic ? quadratic->boundary_nodes.size() : 0},
                {"nodes_on_cad_curves", quadratic ? quadratic->cad_nodes : 0},
                {"max_node_offset", quadratic ? quadratic->max_move : 0.0}};
  j["expected"] = {{"irregular_interior", s.expected_irregular_interior},
                   {"boundary_zeros", s.expected_irregular_boundary},
                   {"euler_characteristic", s.input_euler_characteristic},
                   {"boundary_loops", s.input_boundary_loops},
                   {"quads", result.expected_quads}};
  // the thresholds the quads are judged by (the command line meshes with the
  // defaults): scripts and tests read them from here
  const AcceptanceCriteria criteria;
  j["acceptance"] = {{"min_scaled_jacobian", criteria.min_scaled_jacobian},
                     {"max_mean_angle_deviation_deg", criteria.max_mean_angle_deviation_deg},
                     {"max_hausdorff_relative", criteria.max_hausdorff_relative}};
  j["form"] = {{"coefficients", std::vector<double>(result.coefficients.data(),
                                                     result.coefficients.data() + result.coefficients.size())},
               {"rotate", options.rotate},
               {"attempts", result.form_attempts},
               {"rounding_attempts", result.rounding_attempts},
               {"boundary_tips", result.boundary_tips},
               {"uniformity_ratio", result.uniformity},
               {"scale", result.scale},
               {"size_requested", result.size_requested},
               {"size", result.size},
               {"doubled_genus", result.doubled_genus},
               {"hodge_star_squared", result.residuals.hodge_star_squared}};
  Json zeros = Json::array();
  for (const ZeroVertex& z : result.zero_vertices) {
    if (z.corner) continue;
    const Vec3& p = result.surface.points[static_cast<std::size_t>(z.vertex)];
    zeros.push_back({{"position", {p.x(), p.y(), p.z()}}, {"order", z.order}, {"on_boundary", z.on_boundary}});
  }
  j["zeros"] = zeros;
  Json cones = Json::array();
  const char* interior_reason = options.cone_placement == "cross-field"
                                    ? "a singularity of the smoothest boundary-aligned cross field"
                                    : "Gauss-Bonnet: the quarter turns the corners leave to the inside";
  for (const Cone& c : result.cones) {
    const Vec3& p = result.surface.points[static_cast<std::size_t>(c.vertex)];
    const bool boundary = on_boundary[static_cast<std::size_t>(c.vertex)];
    const char* reason = !boundary                 ? interior_reason
                         : corners.count(c.vertex) ? "corner: one quad per 90 degrees of its angle"
                                                   : "Gauss-Bonnet, on the boundary: no room inside for the cone "
                                                     "(a hole in a part a few quads wide)";
    cones.push_back({{"position", {p.x(), p.y(), p.z()}},
                     {"quads", c.quads},
                     {"on_boundary", boundary},
                     {"reason", reason}});
  }
  const auto share = [](double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); };
  j["singularities"] = {{"mode", options.singularities},
                        {"cone_placement", options.cone_placement},
                        {"route", result.singularities},
                        {"cones", cones},
                        {"size_band", {{"low", size_band_low}, {"high", size_band_high}}},
                        {"size_band_share", share(result.size_band_share)},
                        {"abel_size_band_share", share(result.abel_size_band_share)},
                        {"abel_distance_relative", share(result.abel_distance_relative)},
                        {"cone_route_failure", result.cone_route_failure},
                        {"integer_values", result.cone_map.integer_values},
                        {"max_rounding", result.cone_map.max_rounding},
                        {"stiffening_rounds", result.cone_map.stiffening_rounds},
                        {"factorizations", result.cone_map.factorizations},
                        {"nested_dissection_factorizations", result.cone_map.nested_dissection_factorizations},
                        {"low_rank_columns", result.cone_map.low_rank_columns},
                        {"low_rank_column_solves", result.cone_map.low_rank_column_solves},
                        {"factorization_updates", result.cone_map.factorization_updates},
                        {"lattice_shifts", result.cone_map.lattice_shifts},
                        {"segments_held", result.cone_map.segments_held},
                        {"other_integers", result.cone_map.other_integers},
                        {"rounding_order", result.rounding_order},
                        {"wide_corners_split", result.wide_corners_split}};
  j["zero_order_sum_doubled"] = result.zeros.doubled_order_sum;
  j["flipped_triangles_before"] = result.zeros.flipped_count;
  const Quantization& qz = result.quantization;
  Json periods = Json::array();
  for (const LoopPeriod& p : qz.periods)
    periods.push_back({{"loop", p.loop}, {"before", complex_json(p.before)}, {"after", complex_json(p.after)}});
  j["quantization"] = {{"distortion", qz.distortion},
                       {"periods", periods},
                       {"lattice_zeros", qz.lattice_zeros},
                       {"corners", qz.corners},
                       {"corners_dropped", qz.corners_dropped},
                       {"flipped_triangles", qz.flipped},
                       {"untangled", {{"flipped_before", result.untangle.flipped_before},
                                      {"flipped_after", result.untangle.flipped_after},
                                      {"moved_vertices", result.untangle.moved_vertices}}},
                       {"branch_points", {{"off_the_cones", result.branch_points.hidden},
                                          {"moved_onto_lattice", result.branch_points.snapped}}}};
  const ExtractionReport& x = result.extraction;
  j["extraction"] = {{"cells", x.cells},
                     {"incomplete_cells", x.incomplete_cells},
                     {"degenerate_cells", x.degenerate_cells},
                     {"bad_triangles", x.bad_triangles},
                     {"seam_mismatches", x.seam_mismatches},
                     {"stray_boundary_points", result.stray_boundary_points},
                     {"chords_split", result.chords_split},
                     {"zero_star_splits", result.star_splits}};
  const DeviationRefinementReport& rf = result.refinement;
  j["smoothing"] = {{"moved_points", result.smoothing.moved_points},
                    {"min_scaled_jacobian_before", result.smoothing.min_before},
                    {"min_scaled_jacobian_after", result.smoothing.min_after}};
  j["angle_smoothing"] = {{"moved_points", result.angle_smoothing.moved_points},
                          {"angle_dev_mean_before", result.angle_smoothing.angle_dev_before},
                          {"angle_dev_mean_after", result.angle_smoothing.angle_dev_after}};
  j["fitting"] = {{"moved_points", result.fitting.moved_points},
                  {"deviation_before", result.fitting.deviation_before},
                  {"deviation_after", result.fitting.deviation_after}};
  j["coarsened_from_triangles"] = result.coarsened_from;
  j["surface_triangles"] = result.surface.triangles.size();
  j["long_edges"] = {{"split", result.long_edges_split},
                     {"kept", result.long_edges_split == 0 ? "none split" : result.long_edges_kept ? "split" : "input"}};
  // the tolerance is the fitting's too; chords are split on the Abel route, and on
  // the cone route only where its quads were farther from S than the acceptance
  j["refinement"] = {{"enabled", result.max_deviation > 0 && (result.singularities != "cones" || rf.chords_split > 0)},
                     {"max_deviation", result.max_deviation},
                     {"base_density", result.base_density},
                     {"deviation_before", rf.deviation_before},
                     {"deviation_after", rf.deviation_after},
                     {"tolerance_met", rf.tolerance_met},
                     {"chords_split", rf.chords_split},
                     {"quads_added", rf.quads_added},
                     {"rounds", rf.rounds},
                     {"rounds_undone", rf.rounds_undone}};
  const SizeRefinementReport& sr = result.size_refinement;
  j["size_refinement"] = {{"chords_split", sr.chords_split},
                          {"quads_added", sr.quads_added},
                          {"max_ratio_before", sr.max_ratio_before},
                          {"max_ratio_after", sr.max_ratio_after}};
  Json timings = Json::object();  // a stage run more than once (another form, a coarser base) adds up
  for (const auto& [stage, t] : result.timings) timings[stage] = timings.value(stage, 0.0) + t;
  timings["total"] = seconds;
  j["timings"] = timings;
  s.report = std::move(j);
  return s;
}

void print_summary(const MeshSummary& s) {
  const QuadQuality& q = s.quality;
  fmt::print("quads               {} ({} triangles, {} inverted, {} flipped)\n", q.quads, q.triangles, q.inverted,
             q.flipped);
  fmt::print("irregular vertices  {} interior (zeros predict {}), {} on the boundary ({} boundary zeros)\n",
             q.irregular_interior, s.expected_irregular_interior, q.irregular_boundary,
             s.expected_irregular_boundary);
  fmt::print("scaled Jacobian     min {:.3f}, mean {:.3f} (Verdict)\n", q.min_scaled_jacobian,
             q.mean_scaled_jacobian);
  fmt::print("shape               angles {:.1f}-{:.1f} deg, min warpage {:.3f}, max aspect ratio {:.2f}, max skew "
             "{:.3f}, max taper {:.3f} (Verdict)\n",
             q.min_angle, q.max_angle, q.min_warpage, q.aspect_ratio_max, q.skew_max, q.taper_max);
  if (s.curved)
    fmt::print("curved quads        {} nodes each, min Jacobian ratio {:.3f} ({} elements <= 0)\n", s.nodes_per_quad,
               s.curved->min_ratio, s.curved->non_positive);
  fmt::print("angle deviation     mean {:.2f} deg, p99 {:.2f} deg\n", q.angle_dev_mean, q.angle_dev_p99);
  fmt::print("topology            chi {} (input {}), {} boundary loops (input {})\n", q.euler_characteristic,
             s.input_euler_characteristic, q.boundary_loops, s.input_boundary_loops);
  const Json& abel_distance = s.report["singularities"]["abel_distance_relative"];
  fmt::print("Hausdorff distance  {:.3g} of the diagonal{}\n", q.hausdorff_rel,
             abel_distance.is_number() && s.report["singularities"]["route"].get<std::string>() == "cones"
                 ? fmt::format(" (Abel {:.3g})", abel_distance.get<double>())
                 : std::string());
  if (corners_total(q) > 0)
    fmt::print("corners             {} convex ({} not in one quad), {} concave ({} not in three), {} other ({} wrong)\n",
               q.corners_convex, q.corners_convex_wrong, q.corners_concave, q.corners_concave_wrong, q.corners_other,
               q.corners_other_wrong);
  const Json& sg = s.report["singularities"];
  if (sg["size_band_share"].is_number())
    fmt::print("size                {:.0f}% of the quads within [0.5, 2] x the size ({} route{})\n",
               100 * sg["size_band_share"].get<double>(), sg["route"].get<std::string>(),
               sg["abel_size_band_share"].is_number() && sg["route"].get<std::string>() == "cones"
                   ? fmt::format("; Abel {:.0f}%", 100 * sg["abel_size_band_share"].get<double>())
                   : std::string());
  if (sg["route"].get<std::string>() == "cones")
    fmt::print("quantization        {} cones ({} interior), {} values made integer, largest rounding {:.3g}\n",
               sg["cones"].size(), s.expected_irregular_interior, sg["integer_values"].get<std::size_t>(),
               sg["max_rounding"].get<double>());
  else
    fmt::print("quantization        distortion {:.3g}\n", s.report["quantization"]["distortion"].get<double>());
  if (const auto from = s.report.value("coarsened_from_triangles", std::size_t{0}); from > 0)
    fmt::print("working surface     {} triangles of the input's points (the input has {}; --no-coarsening)\n",
               s.report.value("surface_triangles", std::size_t{0}), from);
  const Json& rf = s.report["refinement"];
  if (rf["enabled"].get<bool>())
    fmt::print("refinement          {} chords split (+{} quads, base lattice {:.0f}% of the target), deviation "
               "{:.3g} -> {:.3g} (tolerance {:.3g})\n",
               rf["chords_split"].get<std::size_t>(), rf["quads_added"].get<std::size_t>(),
               100 * rf["base_density"].get<double>(), rf["deviation_before"].get<double>(),
               rf["deviation_after"].get<double>(), rf["max_deviation"].get<double>());
  if (const Json& sr = s.report["size_refinement"]; sr["chords_split"].get<std::size_t>() > 0)
    fmt::print("size refinement     {} chords split through the quads above {:g} x the size (+{} quads), largest "
               "{:.2f} -> {:.2f} x\n",
               sr["chords_split"].get<std::size_t>(), size_ratio_limit, sr["quads_added"].get<std::size_t>(),
               sr["max_ratio_before"].get<double>(), sr["max_ratio_after"].get<double>());
  if (const Json& ft = s.report["fitting"]; ft["moved_points"].get<std::size_t>() > 0)
    fmt::print("fitting             {} corners moved onto S, deviation {:.3g} -> {:.3g}\n",
               ft["moved_points"].get<std::size_t>(), ft["deviation_before"].get<double>(),
               ft["deviation_after"].get<double>());
  fmt::print("time                {:.2f} s\n", s.seconds);
}

void write_report(const std::string& path, const MeshSummary& summary) {
  std::ofstream out(path);
  // a file name that is not UTF-8 (the input's) is written with U+FFFD, not refused
  out << summary.report.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
  out.close();  // the last buffer is written here: check after it
  if (!out) throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write the report", path));
}

}  // namespace qm::tools
