#include "libquadmesh/cones/cone_map.h"

#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/cone_winding.h"
#include "libquadmesh/cones/tip_scale.h"
#include "libquadmesh/cones/tip_shear.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>

namespace qm {

namespace {

/// The most the field may miss itself across a seam (radians): the cones' turns
/// are whole quarter turns by construction, so what is left is the solve's
/// rounding, summed along the field's transport (2e-6 on a 69,000-triangle scan).
/// A cone set whose holonomy is not a multiple of pi/2 misses by far more.
constexpr double max_seam_misalignment = 1e-4;

/// The lattice shifts (lattice units, from the values' circular mean:
/// seamless_map.h) a map folded round one misturned cone is quantized from again,
/// in order. Bunny-open's nearer capped cones at 1.5%: the map folds round a
/// valence-5 cone, and from the circular mean too; moved half a quad along Re from
/// there, nothing folds and 95% of the quads are in the size band. Measured with
/// every map from the circular mean (the shared meshes, examples, parts and scan
/// cuts at 1.5%), of 68 maps folded round misturned cones a half-quad shift
/// unfolded 5 of the 26 with one such cone, 1 of the 15 with two and none of the
/// 27 with more (those are the placement's, not the rounding's: the cones are
/// placed again, cone_route.cpp).
constexpr Complex lattice_shifts[] = {{0, 0}, {0.5, 0}, {0, 0.5}, {0.5, 0.5}};

/// The mean of u over the neighbours of v.
double ring_mean(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u, std::size_t v) {
  const VertexRing ring = vertex_ring(soup, adjacency, static_cast<int>(v));
  double sum = 0;
  for (int w : ring.neighbours) sum += u[w];
  return ring.neighbours.empty() ? u[static_cast<Eigen::Index>(v)] : sum / static_cast<double>(ring.neighbours.size());
}

}  // namespace

ConeMap cone_map(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<Cone>& cones,
                 double size, RoundingOrder order, const StopRequest& stop, const SurfaceSolvers* shared) {
  QM_ASSERT(size > 0 && adjacency.soup == &soup);
  QM_ASSERT(!shared || (&shared->metrics.soup() == &soup && &shared->potentials.soup() == &soup));
  ConeMap out;
  out.quads = quads_per_vertex(adjacency, cones);
  require_gauss_bonnet(adjacency, out.quads, euler_characteristic(adjacency));
  const std::vector<double> target = target_curvature(adjacency, out.quads);
  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  out.u = shared ? shared->metrics.solve(target, curvature) : cone_metric(soup, adjacency, target, curvature);
  out.field = cone_cross_field(soup, adjacency, out.u, shared ? &shared->potentials : nullptr);
  if (out.field.misaligned_loop >= 0)
    throw Error(ErrorCode::unsupported,
                "boundary loop " + std::to_string(out.field.misaligned_loop) + " is turned by " +
                    std::to_string(out.field.max_misalignment * 180 / M_PI) +
                    " degrees against the cones' cross field: these cones give no quad mesh");
  if (out.field.max_seam_misalignment > max_seam_misalignment)
    throw Error(ErrorCode::unsupported,
                "the cones' cross field misses itself by " +
                    std::to_string(out.field.max_seam_misalignment * 180 / M_PI) +
                    " degrees around a handle: these cones give no quad mesh");
  out.cut = cut_graph(soup, adjacency, out.field, out.quads);
  // u has a logarithmic singularity at an interior cone; its value there is the
  // discretization's, not the metric's, and would shrink (valence 5) or swell
  // (valence 3) the cone's star in the fit: there the fit takes the neighbours'
  // scale (the field keeps u as it is: its turning needs it)
  Eigen::VectorXd scale = out.u;
  for (std::size_t v = 0; v < out.quads.size(); ++v)
    if (!adjacency.boundary_vertex[v] && out.quads[v] != 4)
      scale[static_cast<Eigen::Index>(v)] = ring_mean(soup, adjacency, out.u, v);
  // an acute corner's singular scale left out near it: the map sheared there
  // rather than its quads swollen (tip_scale.h)
  const std::vector<AcuteTip> tips = acute_tips(soup, adjacency, target, curvature, size);
  scale += tip_scale_offset(soup, adjacency, tips, scale);
  // and the map sheared at each tip, its quad a parallelogram along the tip's
  // edges (tip_shear.h)
  const FitShape shape = tip_shear(soup, adjacency, tips, out.field, size);
  // the maps below share one system pattern, so one fill-reducing ordering
  MapOrdering ordering;
  out.map = seamless_map(soup, adjacency, scale, out.field, out.cut, out.quads, size, out.report, order, &shape, {},
                         stop, &ordering);
  if (out.report.inverted_triangles > 0) out.misturned = misturned_cones(soup, adjacency, out.map, out.quads);
  // a map folded round one cone it winds a turn short is quantized again from
  // chosen offsets of the lattice (the rounding then takes other integers from the
  // start), in order while the kept map is so folded: a map with fewer folds is
  // kept. As many offsets are mapped at once as there are worker threads, and
  // taken in order (a map past the one that ends it is dropped): the same map on
  // any number of threads
  const std::size_t shifts = std::size(lattice_shifts);
  std::size_t next = 0;  // the offsets taken so far
  while (next < shifts && out.misturned.size() == 1) {
    stop_if_requested(stop);  // (each offset's map runs to its end: a loop body must not throw)
    const std::size_t width = std::min(shifts - next, std::max<std::size_t>(1, worker_threads()));
    std::vector<FaceMap> maps(width);
    std::vector<SeamlessMapReport> reports(width);
    parallel_for_index(width, [&](std::size_t i) {
      maps[i] = seamless_map(soup, adjacency, scale, out.field, out.cut, out.quads, size, reports[i], order, &shape,
                             lattice_shifts[next + i], {}, &ordering);
    });
    for (std::size_t i = 0; i < width && out.misturned.size() == 1; ++i, ++next) {
      if (reports[i].inverted_triangles >= out.report.inverted_triangles) continue;
      out.map = std::move(maps[i]);
      out.report = reports[i];
      out.misturned = out.report.inverted_triangles > 0 ? misturned_cones(soup, adjacency, out.map, out.quads)
                                                        : std::vector<int>{};
    }
  }
  out.report.lattice_shifts = static_cast<int>(next);
  // a map still folded where it has boundary segments under a quad and a half
  // between corners: mapped again with those held to one quad in the fit
  // (seamless_map.h), and kept when it folds less (a scan's hole polygons, their
  // corners a fraction of a quad apart: a kitten cut with two holes kept the Abel
  // quads before, its nearest cone map 10 folded triangles and 3 cells dropped)
  if (out.report.inverted_triangles > 0 && out.report.short_segments > 0) {
    stop_if_requested(stop);
    SeamlessMapReport held_report;
    std::optional<FaceMap> held;
    try {
      held = seamless_map(soup, adjacency, scale, out.field, out.cut, out.quads, size, held_report, order, &shape, {},
                          stop, nullptr, true);
    } catch (const Stopped&) {
      throw;
    } catch (const Error&) {
      // no held map (its system not factored): the folded one stands
    }
    if (held && held_report.inverted_triangles < out.report.inverted_triangles) {
      held_report.lattice_shifts = out.report.lattice_shifts;
      out.map = std::move(*held);
      out.report = held_report;
      out.misturned = out.report.inverted_triangles > 0 ? misturned_cones(soup, adjacency, out.map, out.quads)
                                                        : std::vector<int>{};
    }
  }
  return out;
}

}  // namespace qm
