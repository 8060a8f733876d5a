#include "libquadmesh/core/mesh.h"
#include "io/write_views.h"
#include "libquadmesh/forms/boundary_chords.h"
#include "libquadmesh/forms/cotan_repair.h"
#include "libquadmesh/forms/cut_integration.h"
#include "libquadmesh/forms/named_loops.h"
#include "libquadmesh/forms/remesh.h"
#include "libquadmesh/quality/triangle_quality.h"
#include "libquadmesh/forms/symmetric_forms.h"
#include "tools/common/exit_codes.h"
#include "tools/common/input_surface.h"
#include "tools/common/output_paths.h"
#include "tools/common/usage_error.h"
#include "tools/quadmesh/commands.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace qm::tools {

namespace {

using Json = nlohmann::ordered_json;

/// The zeros listed on S: clusters with a nonzero order whose representative is a
/// vertex of S (a mirror pair is listed once, by its + member).
std::vector<const ZeroCluster*> surface_zeros(const SymmetricForms& forms) {
  std::vector<const ZeroCluster*> out;
  for (const ZeroCluster& c : forms.zeros.clusters)
    if (c.order != 0 && c.representative >= 0 &&
        static_cast<std::size_t>(c.representative) < forms.doubled.input_vertices)
      out.push_back(&c);
  return out;
}

Json zeros_json(const SymmetricForms& forms, const TriangleSoup& soup) {
  Json list = Json::array();
  for (const ZeroCluster* zero : surface_zeros(forms)) {
    const ZeroCluster& c = *zero;
    const Vec3& p = soup.points[static_cast<std::size_t>(c.representative)];
    const std::int64_t label = soup.point_label(c.representative);
    list.push_back({{"vertex", label >= 0 ? Json(label) : Json(nullptr)},
                    {"position", {p.x(), p.y(), p.z()}},
                    {"order", c.order},
                    {"on_boundary", c.on_boundary},
                    {"flipped_triangles", c.flipped_triangles}});
  }
  return list;
}

/// The input triangulation with the forms as Gmsh views (method.md section 6 figures).
void write_form_views(const std::string& path, const SymmetricForms& forms,
                      const AnalyzedSurface& surface, const Mesh& mesh_s) {
  const Mesh& D = forms.doubled.mesh;
  const std::size_t faces = forms.doubled.input_faces;
  io::OutputMesh mesh;
  mesh.points = surface.soup.points;
  for (std::size_t f = 0; f < faces; ++f) {
    const auto c = face_corners(D, Mesh::Face_index(static_cast<Mesh::size_type>(f)));
    mesh.faces.push_back({c[0], c[1], c[2]});
  }
  const NamedLoops loops = named_loops(mesh_s);
  auto add_lines = [&](const char* kind, const std::vector<std::vector<int>>& list, bool closed) {
    for (std::size_t l = 0; l < list.size(); ++l) {
      // loops count from 0; bridge k (from 1) joins boundary 0 to boundary k
      io::LineGroup group{fmt::format("{}_{}", kind, closed ? l : l + 1), {}, {}};
      const auto& p = list[l];
      for (std::size_t i = 0; i + 1 < p.size(); ++i) group.edges.push_back({p[i], p[i + 1]});
      if (closed && p.size() > 2) group.edges.push_back({p.back(), p.front()});
      mesh.line_groups.push_back(std::move(group));
    }
  };
  add_lines("boundary", loops.boundaries, true);
  add_lines("bridge", loops.bridges, false);
  add_lines("handle", loops.handles, true);
  io::PointGroup zeros{"zeros", {}};
  for (const ZeroCluster* c : surface_zeros(forms)) zeros.points.push_back(c->representative);
  if (!zeros.points.empty()) mesh.point_groups.push_back(std::move(zeros));

  std::vector<io::FaceVectorView> vectors;
  std::vector<io::CornerScalarView> scalars;
  const auto re = face_covectors(D, forms.symmetric.real_part);
  for (int k = 0; k < forms.symmetric.dimension(); ++k) {
    vectors.push_back({fmt::format("form {}: Re h (vector per triangle)", k + 1),
                       re[static_cast<std::size_t>(k)].topRows(static_cast<Eigen::Index>(faces))});
    scalars.push_back({fmt::format("form {}: Re of the integral (cut surface)", k + 1),
                       integrate_on_cut_surface(D, forms.symmetric.real_part.col(k), faces)});
    scalars.push_back({fmt::format("form {}: Im of the integral (cut surface)", k + 1),
                       integrate_on_cut_surface(D, forms.symmetric.imaginary_part.col(k), faces)});
  }
  io::write_views(path, mesh, vectors, scalars);
}

/// The work limit of --remesh-size, before the remeshing: the triangles it
/// implies (area over an equilateral triangle's, sqrt(3)/4 H^2) against --max-triangles.
void check_triangle_estimate(const FormsOptions& options, const TriangleSoup& soup) {
  if (options.remesh_size <= 0) return;
  const double estimate = total_area(soup) / (0.25 * std::sqrt(3.0) * options.remesh_size * options.remesh_size);
  if (!(estimate > static_cast<double>(options.max_triangles))) return;
  throw UsageError(fmt::format("--remesh-size {:g} implies about {:.3g} triangles, more than --max-triangles {}; "
                               "give a larger --remesh-size, or raise --max-triangles",
                               options.remesh_size, std::min(estimate, 1e300), options.max_triangles));
}

}  // namespace

int run_forms(const FormsOptions& options, const CommonOptions& common) {
  const Progress progress(common.quiet || options.json);
  io::ReadOptions read;
  read.cad_mesh_size = common.cad_mesh_size;
  check_output_file({"-o", options.views}, io::Format::msh);
  check_distinct({{"the input", options.input}, {"-o", options.views}});
  InputSurface in = load_input_surface(options.input, read, common.largest_component, progress);
  require_supported(in.surface);
  check_triangle_estimate(options, in.surface.soup);
  const TriangleQuality input_quality = triangle_quality(in.surface.soup);
  const bool remeshed = options.remesh || options.remesh_size > 0;
  if (remeshed) {
    RemeshOptions remesh;
    remesh.target_edge_length = options.remesh_size;
    progress.stage(fmt::format("remeshing isotropically (target edge length {:.4g})",
                               remesh_target(in.surface.soup, remesh)));
    in.surface = analyze_topology(remesh_isotropic(in.surface.soup, remesh));
    require_supported(in.surface);
  }
  CotanRepairReport repair;
  if (options.repair) {
    progress.stage("curing negative cotangent weights (flips and splits)");
    Mesh repaired = to_surface_mesh(in.surface.soup);
    repair = repair_cotan_weights(repaired);
    in.surface.soup = soup_of(repaired, in.surface.soup);
  }
  const TriangleQuality quality =
      remeshed || options.repair ? triangle_quality(in.surface.soup) : input_quality;
  const std::size_t chords = split_boundary_chords(in.surface.soup);
  progress.stage(fmt::format("computing symmetric holomorphic forms ({} boundary chords split)", chords));
  const Mesh mesh = to_surface_mesh(in.surface.soup);
  const SymmetricForms forms = compute_symmetric_forms(mesh);
  const FormsResiduals& r = forms.residuals;

  Json j;
  j["doubled_genus"] = forms.doubled_genus;
  j["symmetric_dimension"] = forms.symmetric.dimension();
  j["euler_characteristic"] = in.surface.report.euler_characteristic;
  j["boundary_chords_split"] = chords;
  auto quality_json = [](const TriangleQuality& q) {
    return Json{{"triangles", q.triangles}, {"min_angle_deg", q.min_angle_deg},
                {"max_angle_deg", q.max_angle_deg}, {"slivers", q.slivers}, {"obtuse", q.obtuse}};
  };
  j["input_triangulation"] = quality_json(input_quality);
  j["remeshed"] = remeshed;
  j["triangulation"] = quality_json(quality);
  if (options.repair)
    j["repair"] = {{"negative_weights_before", repair.negative_before},
                   {"negative_weights_after", repair.negative_after},
                   {"flips", repair.flips},
                   {"interior_splits", repair.interior_splits},
                   {"boundary_splits", repair.boundary_splits}};
  j["zeros_of"] = "symmetric basis form 1";
  j["zeros"] = zeros_json(forms, in.surface.soup);
  j["zero_order_sum_doubled"] = forms.zeros.order_sum;
  j["flipped_triangles"] = forms.zeros.flipped_count;
  j["residuals"] = {{"closedness", r.closedness},
                    {"coclosedness", r.coclosedness},
                    {"hodge_star_squared", r.hodge_star_squared},
                    {"boundary_imaginary", r.boundary_imaginary},
                    {"symmetry", r.symmetry}};
  Json timings = Json::object();
  for (const auto& [stage, seconds] : forms.timings) timings[stage] = seconds;
  j["timings"] = timings;

  if (r.hodge_star_squared > 0.1)
    fmt::print(stderr,
               "quadmesh: warning: ||Lambda^2 + I|| = {:.3g} > 0.1: the forms are inaccurate on this "
               "triangulation ({} slivers under 5 degrees, {} obtuse of {} triangles){}\n",
               r.hodge_star_squared, quality.slivers, quality.obtuse, quality.triangles,
               remeshed ? "; try a smaller --remesh-size" : "; try --remesh");
  if (!options.views.empty()) {
    progress.stage(fmt::format("writing the views to {}", options.views));
    try {
      write_form_views(options.views, forms, in.surface, mesh);
    } catch (const Error& e) {  // an output path problem (exit 2), and nothing left
      throw UsageError(e.what());
    }
  }
  if (options.json) {
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("doubled genus       {}\n", forms.doubled_genus);
    fmt::print("symmetric forms     {}\n", forms.symmetric.dimension());
    fmt::print("zeros (form 1)      {} on the surface, orders summing to {} on the double "
               "(expected 2G - 2 = {}), {} folded triangles\n",
               j["zeros"].size(), forms.zeros.order_sum, 2 * forms.doubled_genus - 2,
               forms.zeros.flipped_count);
    fmt::print("residuals           closedness {:.2e}, co-closedness {:.2e}, |Lambda^2 + I| "
               "{:.3g}, boundary Im {:.2e}, symmetry {:.2e}\n",
               r.closedness, r.coclosedness, r.hodge_star_squared, r.boundary_imaginary,
               r.symmetry);
    double total = 0;
    for (const auto& t : forms.timings) total += t.second;
    fmt::print("time                {:.3f} s\n", total);
  }
  return exit_ok;
}

}  // namespace qm::tools
