#include "libquadmesh/pipeline/internal/form_setup.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/boundary_chords.h"
#include "libquadmesh/forms/remesh.h"
#include "libquadmesh/param/boundary_tips.h"
#include "libquadmesh/param/surface_forms.h"
#include "libquadmesh/quality/hausdorff.h"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace qm {

namespace {

/// RemeshPolicy::automatic remeshes when ||Lambda^2 + I|| exceeds this on the
/// input (the forms are then inaccurate).
constexpr double max_hodge_star_residual = 0.1;

/// The automatic remeshing's edge length: this fraction of the mean edge...
constexpr double remesh_mean_edge_fraction = 0.4;
/// ...or this fraction of the quad edge, whichever is smaller.
constexpr double remesh_quads_per_edge = 3.0;

double surface_area(const TriangleSoup& soup) {
  double area = 0;
  for (const Triangle& t : soup.triangles)
    area += 0.5 * (soup.points[static_cast<std::size_t>(t[1])] - soup.points[static_cast<std::size_t>(t[0])])
                      .cross(soup.points[static_cast<std::size_t>(t[2])] - soup.points[static_cast<std::size_t>(t[0])])
                      .norm();
  return area;
}

/// The coefficients of h the options ask for (QuadMeshOptions::coefficients or
/// ::form); auto's are left to choose_form.
void asked_coefficients(const QuadMeshOptions& options, FormSetup& setup) {
  QuadMeshResult& r = setup.preamble;
  const int G = static_cast<int>(setup.basis.size());
  if (!options.coefficients.empty()) {
    if (static_cast<int>(options.coefficients.size()) != G)
      throw Error(ErrorCode::bad_input,
                  fmt::format("QuadMeshOptions::coefficients has {} values but the surface has {} symmetric forms",
                              options.coefficients.size(), G),
                  "QuadMeshOptions::coefficients");
    r.coefficients = Eigen::Map<const Eigen::VectorXd>(options.coefficients.data(), G);
    if (r.coefficients.norm() == 0)
      throw Error(ErrorCode::bad_input, "QuadMeshOptions::coefficients: all coefficients are 0",
                  "QuadMeshOptions::coefficients");
    r.coefficients.normalize();
  } else if (options.form >= 0) {
    if (options.form >= G)
      throw Error(ErrorCode::bad_input,
                  fmt::format("QuadMeshOptions::form = {}: the surface has {} symmetric forms (0 to {})",
                              options.form, G, G - 1),
                  "QuadMeshOptions::form");
    r.coefficients = Eigen::VectorXd::Unit(G, options.form);
  }
}

/// Remeshes `soup` isotropically for the forms (QuadMeshOptions::remesh_size, or
/// the smaller of remesh_mean_edge_fraction x its mean edge and a
/// remesh_quads_per_edge-th of r.size_requested); notes it in `r`.
void remesh_for_forms(TriangleSoup& soup, const QuadMeshOptions& options, Stages& stages, QuadMeshResult& r) {
  RemeshOptions remesh_options;
  remesh_options.target_edge_length =
      options.remesh_size > 0 ? options.remesh_size
                              : std::min(remesh_mean_edge_fraction * mean_edge_length(soup),
                                         r.size_requested / remesh_quads_per_edge);
  stages.next("remeshing", fmt::format("remeshing isotropically (edge length {:.4g})", remesh_options.target_edge_length));
  soup = remesh_isotropic(soup, remesh_options);
  r.remeshed = true;
}

}  // namespace

RequestedSize requested_size(const TriangleSoup& soup, const QuadMeshOptions& options) {
  const double diagonal = bounding_box_diagonal(soup.points, soup.triangles);
  RequestedSize r;
  r.size = options.size > 0            ? options.size
           : options.size_relative > 0 ? options.size_relative * diagonal
                                       : diagonal / default_size_divisions;
  r.edge = options.quads > 0 ? std::sqrt(surface_area(soup) / static_cast<double>(options.quads)) : r.size;
  return r;
}

double implied_quad_count(const TriangleSoup& soup, const QuadMeshOptions& options) {
  if (options.quads > 0) return static_cast<double>(options.quads);
  const double size = requested_size(soup, options).size;
  return surface_area(soup) / (size * size);
}

void require_within_work_limit(const TriangleSoup& soup, const QuadMeshOptions& options) {
  if (options.max_quads == 0) return;
  const double quads = implied_quad_count(soup, options);
  if (quads <= static_cast<double>(options.max_quads)) return;  // NaN refused too
  throw Error(ErrorCode::bad_input,
              fmt::format("the size asked for implies about {:.3g} quads (surface area / size^2), more than "
                          "QuadMeshOptions::max_quads {}",
                          std::min(quads, 1e300), options.max_quads),
              "QuadMeshOptions::max_quads");
}

FormSetup prepare_surface(TriangleSoup soup, SurfaceTopology topology, const QuadMeshOptions& options,
                          Stages& stages) {
  FormSetup setup;
  QuadMeshResult& r = setup.preamble;
  setup.area = surface_area(soup);
  setup.diagonal = bounding_box_diagonal(soup.points, soup.triangles);
  r.size_requested = requested_size(soup, options).edge;  // with a quad count, the edge of a square of area / quads
  if (options.remesh == RemeshPolicy::always) remesh_for_forms(soup, options, stages, r);
  r.chords_split = split_boundary_chords(soup);
  // with boundary, the doubled surface's genus is 2g + b - 1 = 1 - chi
  r.doubled_genus = 1 - topology.euler_characteristic;
  const double not_computed = std::numeric_limits<double>::quiet_NaN();
  r.residuals = FormsResiduals{not_computed, not_computed, not_computed, not_computed, not_computed};
  r.input_hodge_star_squared = not_computed;
  setup.soup = std::move(soup);
  return setup;
}

bool compute_forms(FormSetup& setup, const QuadMeshOptions& options, Stages& stages) {
  QuadMeshResult& r = setup.preamble;
  TriangleSoup& soup = setup.soup;
  stages.next("forms", "computing symmetric holomorphic forms");
  SymmetricForms forms = compute_symmetric_forms(to_surface_mesh(soup));
  r.input_hodge_star_squared = forms.residuals.hodge_star_squared;
  const bool remeshed =
      options.remesh == RemeshPolicy::automatic && forms.residuals.hodge_star_squared > max_hodge_star_residual;
  if (remeshed) {
    remesh_for_forms(soup, options, stages, r);
    stages.next("forms", fmt::format("computing the forms again (||Lambda^2 + I|| was {:.3g})",
                                      r.input_hodge_star_squared));
    r.chords_split += split_boundary_chords(soup);
    forms = compute_symmetric_forms(to_surface_mesh(soup));
  }
  r.doubled_genus = forms.doubled_genus;
  r.residuals = forms.residuals;
  setup.basis = symmetric_face_maps(forms, soup);
  asked_coefficients(options, setup);
  setup.loops = period_loops(soup);  // of S before any cone star is refined
  setup.forms_computed = true;
  return remeshed;
}

FormSetup prepare_forms(TriangleSoup soup, const QuadMeshOptions& options, Stages& stages) {
  const SurfaceTopology topology = topology_of(soup);
  FormSetup setup = prepare_surface(std::move(soup), topology, options, stages);
  compute_forms(setup, options, stages);
  return setup;
}

void choose_form(FormSetup& setup, const QuadMeshOptions& options, Stages& stages) {
  QuadMeshResult& r = setup.preamble;
  if (r.coefficients.size() > 0) return;  // asked for, or chosen before
  stages.next("form_choice", "choosing the form");
  const TipChoice choice = most_uniform_with_tips(setup.soup, surface_adjacency(setup.soup), setup.basis,
                                                  options.tip_angle_deg * M_PI / 180.0);
  r.boundary_tips = choice.tips.size();
  r.coefficients = choice.coefficients;
  if (!choice.tips.empty()) setup.free_coefficients = choice.free_coefficients;
}

}  // namespace qm
