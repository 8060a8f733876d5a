#include "libquadmesh/pipeline/internal/attempt.h"

#include "libquadmesh/forms/named_loops.h"
#include "libquadmesh/param/barrier_untangle.h"
#include "libquadmesh/param/form_choice.h"
#include "libquadmesh/param/rounding_scale.h"
#include "libquadmesh/param/surface_forms.h"
#include "libquadmesh/param/untangle.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace qm {

namespace {

/// How far from the requested size the scale may move to round the periods better
/// (rounding_scale.h): 3% in s, 6% in the quad count.
constexpr double rounding_window = 0.03;

/// At least this many quad edges on every boundary loop (the loop's U-variation,
/// in cells, that the scale must reach)...
constexpr double min_boundary_loop_cells = 4.5;
/// ...but not at any price: a form almost 0 along a loop would be scaled up a
/// thousandfold (a lattice of millions of cells); beyond this factor of the scale
/// the loop keeps fewer edges.
constexpr double max_boundary_scale_factor = 2.0;

/// Zeros closer than this in the image of s h (cells) cannot be separated by the
/// grid and are merged; a boundary zero this close to a sharp corner moves onto it
/// (zero_stars.h).
constexpr double zero_separation_cells = 1.0;

/// An untangling pass one vertex at a time is kept only if no image edge grows
/// beyond this factor of the longest before it (each move stays within twice its
/// star, but a hundred sweeps of them can spread a region over thousands of cells).
constexpr double max_image_edge_growth = 2.0;


double longest_image_edge(const FaceMap& map) {
  double longest = 0;
  for (const CornerValues& c : map.corners)
    longest = std::max({longest, std::abs(c[1] - c[0]), std::abs(c[2] - c[1]), std::abs(c[0] - c[2])});
  return longest;
}

/// h = sum c_k h_k, conjugated with the basis when that keeps the input's orientation.
FaceMap oriented_form(std::vector<FaceMap>& basis, const Eigen::VectorXd& coefficients) {
  FaceMap h = linear_combination(basis, coefficients);
  if (total_image_area(h) < 0) {  // keep the input's orientation
    h = conjugated(h);
    for (FaceMap& b : basis) b = conjugated(b);
  }
  return h;
}

/// The scale s (quads ~ area / size^2 = s^2 sum |h|^2 dA): `density` x the target
/// count, moved within rounding_window to where the periods round best when asked,
/// then raised for the boundary loops' minimum of edges. Sets expected_quads,
/// scale, base_density and size of `r`; returns s h.
FaceMap scale_form(const FormSetup& setup, const QuadMeshOptions& options, const AttemptRequest& request,
                   const SurfaceAdjacency& input, const FaceMap& h, QuadMeshResult& r) {
  r.expected_quads = options.quads > 0 ? static_cast<double>(options.quads)
                                       : setup.area / (r.size_requested * r.size_requested);
  const double nominal = std::sqrt(r.expected_quads / image_area_sum(h));
  r.scale = std::sqrt(request.density) * nominal;
  if (request.choose_scale)
    r.scale = rounding_scale(rounded_periods(input, h, setup.loops), r.scale, rounding_window);
  r.base_density = (r.scale / nominal) * (r.scale / nominal);
  const double count_scale = r.scale;
  for (const auto& loop : input.boundary_loops) {
    double variation = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
      variation += std::abs(edge_value(input, h, loop[i], loop[(i + 1) % loop.size()]).real());
    if (variation > 0 && r.scale * variation < min_boundary_loop_cells)
      r.scale = std::min(min_boundary_loop_cells / variation, max_boundary_scale_factor * count_scale);
  }
  r.size = std::sqrt(setup.area / (r.scale * r.scale * image_area_sum(h)));
  return scaled(h, r.scale);
}

/// The zeros of s h placed at vertices, close ones merged, then the sharp
/// boundary corners (r.zeros, r.zero_vertices).
void place_zeros(const TriangleSoup& soup, const SurfaceAdjacency& input, const FaceMap& target,
                 const QuadMeshOptions& options, QuadMeshResult& r) {
  r.zeros = map_zeros(soup, input, target);
  for (const MapZero& z : r.zeros.zeros)
    if (z.order > 0 && z.representative >= 0) r.zero_vertices.push_back({z.representative, z.order, z.on_boundary});
  r.zero_vertices = merge_close_zeros(soup, input, target, r.zero_vertices, zero_separation_cells);
  r.zero_vertices = add_corners(soup, input, target, r.zero_vertices,
                                boundary_corners(soup, input, options.corner_angle_deg, r.size, r.zero_vertices),
                                zero_separation_cells);
}

/// Per vertex: 1 a cone, 2 in a cone's star (the model star is fold-free by
/// construction; an average cannot reproduce an image angle other than 2 pi), 0 free.
std::vector<char> pinned_vertices(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                  const std::vector<ZeroVertex>& cones) {
  std::vector<char> pinned(soup.points.size(), 0);
  for (const ZeroVertex& z : cones) pinned[static_cast<std::size_t>(z.vertex)] = 1;
  for (const ZeroVertex& z : cones)
    for (int v : vertex_ring(soup, adjacency, z.vertex).neighbours)
      if (!pinned[static_cast<std::size_t>(v)]) pinned[static_cast<std::size_t>(v)] = 2;
  return pinned;
}

/// All the vertices around the folds at once; what that leaves, one at a time.
/// Each pass is added to r.untangle (flipped_after: the last pass's).
void untangle_folds(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<char>& pinned,
                    QuadMeshResult& r) {
  auto absorb = [&](const UntangleReport& pass) {
    r.untangle.flipped_after = pass.flipped_after;
    r.untangle.moved_vertices += pass.moved_vertices;
    r.untangle.rounds += pass.rounds;
  };
  const UntangleReport barrier = untangle_by_barrier(soup, adjacency, r.quantization.param, pinned);
  absorb(barrier);
  if (barrier.flipped_after == 0) return;
  const FaceMap before = r.quantization.param;
  const UntangleReport local = untangle(soup, adjacency, r.quantization.param, pinned);
  if (local.flipped_after < barrier.flipped_after &&
      longest_image_edge(r.quantization.param) <= max_image_edge_growth * longest_image_edge(before))
    absorb(local);
  else
    r.quantization.param = before;
}

/// The quantization (quantization.h), then the local repair of the folds it left
/// and the cones the untangled map hides (r.quantization, untangle, branch_points).
void quantize_and_untangle(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& target,
                           const std::vector<FaceMap>& basis, const NamedLoops& loops, Stages& stages,
                           QuadMeshResult& r) {
  r.quantization = quantize(soup, adjacency, target, basis, r.zero_vertices, loops);
  auto unsafe = [&] {
    return std::count_if(r.quantization.param.corners.begin(), r.quantization.param.corners.end(),
                         [](const CornerValues& c) { return !safely_positive(c); });
  };
  std::vector<char> pinned = pinned_vertices(soup, adjacency, r.zero_vertices);  // snap_hidden_cones adds to it
  const auto folds = unsafe();
  if (folds == 0) return;
  stages.next("untangling", fmt::format("untangling {} folded or nearly flat triangles", folds));
  r.untangle.flipped_before = count_flipped(r.quantization.param);
  untangle_folds(soup, adjacency, pinned, r);
  // the untangled map may branch beside a cone rather than at it
  r.branch_points = snap_hidden_cones(soup, adjacency, r.quantization.param, r.zero_vertices, pinned);
  if (r.branch_points.snapped > 0 && unsafe() > 0) untangle_folds(soup, adjacency, pinned, r);
  if (r.branch_points.hidden > 0) r.zero_vertices = mapped_cones(soup, adjacency, r.quantization.param, r.zero_vertices);
}

/// The quads of the lattice (r.quads, extraction) and the input boundary loop of
/// each quad point (r.boundary_loop_of_point).
void extract_quads(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const NamedLoops& loops,
                   Stages& stages, QuadMeshResult& r) {
  stages.next("extraction", "extracting the quads");
  r.quads = extract_lattice_quads(soup, adjacency, r.quantization.param, r.extraction);
  compact(r.quads);
  r.boundary_loop_of_point = boundary_loop_of_points(soup, adjacency, loops, r.quads);
}

}  // namespace

void compact(LatticeQuads& q) {
  std::vector<int> index(q.points.size(), -1);
  LatticeQuads out;
  for (auto& quad : q.quads)
    for (int& v : quad) {
      if (index[static_cast<std::size_t>(v)] < 0) {
        index[static_cast<std::size_t>(v)] = static_cast<int>(out.points.size());
        out.points.push_back(q.points[static_cast<std::size_t>(v)]);
        out.locations.push_back(q.locations[static_cast<std::size_t>(v)]);
      }
      v = index[static_cast<std::size_t>(v)];
    }
  out.quads = std::move(q.quads);
  q = std::move(out);
}

std::vector<int> boundary_loop_of_points(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                         const NamedLoops& loops, const LatticeQuads& quads) {
  const std::vector<int> loop_of = boundary_loop_of_vertex(loops, soup.points.size());
  std::vector<int> out;
  for (const SurfaceLocation& loc : quads.locations) {
    int loop = -1;
    if (loc.kind == SurfaceLocation::Kind::vertex) loop = loop_of[static_cast<std::size_t>(loc.a)];
    if (loc.kind == SurfaceLocation::Kind::edge && adjacency.is_boundary_edge(loc.a, loc.b))
      loop = loop_of[static_cast<std::size_t>(loc.a)];
    out.push_back(loop);
  }
  return out;
}

void note_stray_boundary(QuadMeshResult& r) {
  const std::vector<int> stray = stray_boundary_points(r.quads, r.boundary_loop_of_point);
  r.stray_boundary_points = stray.size();
  if (!stray.empty()) r.first_stray_point = r.quads.points[static_cast<std::size_t>(stray.front())];
}

NamedLoops period_loops(const TriangleSoup& soup) { return named_loops(to_surface_mesh(soup)); }

Candidate mesh_attempt(const FormSetup& setup, const QuadMeshOptions& options, const AttemptRequest& request,
                       Stages& stages) {
  QuadMeshResult r = setup.preamble;
  TriangleSoup soup = setup.soup;          // refined around the zeros below
  std::vector<FaceMap> basis = setup.basis;  // (the same triangles as soup)
  r.coefficients = request.coefficients;
  r.boundary_tips = request.boundary_tips;
  r.uniformity = uniformity_ratio(soup, basis, r.coefficients);
  const FaceMap h = oriented_form(basis, r.coefficients);
  FaceMap target;
  {
    // S as it is until the cone stars are refined
    const SurfaceAdjacency input = surface_adjacency(soup);
    target = scale_form(setup, options, request, input, h, r);
    stages.next("zeros", "placing the zeros at vertices");
    place_zeros(soup, input, target, options, r);
  }
  {
    std::vector<FaceMap*> maps{&target};
    for (FaceMap& b : basis) maps.push_back(&b);
    r.star_splits = refine_zero_stars(soup, maps, r.zero_vertices);
  }
  stages.next("quantization", "quantizing (integer periods, boundary levels, zeros and corners on the lattice)");
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const NamedLoops loops = period_loops(soup);
  quantize_and_untangle(soup, adjacency, target, basis, loops, stages, r);
  if (options.rotate)  // i h: a quarter turn of the plane maps the lattice onto itself
    r.quantization.param = scaled(r.quantization.param, Complex(0, 1));
  extract_quads(soup, adjacency, loops, stages, r);
  r.surface = std::move(soup);
  note_stray_boundary(r);
  Candidate c;
  c.quality = assess_candidate(r);
  c.result = std::move(r);
  return c;
}

}  // namespace qm
