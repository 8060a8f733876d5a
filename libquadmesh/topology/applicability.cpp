#include "libquadmesh/topology/applicability.h"

#include "libquadmesh/topology/internal/soup_cleaning.h"

#include <fmt/format.h>

namespace qm {

namespace {

Applicability refuse(SurfaceCase kind, ErrorCode code, std::string reason) {
  Applicability a;
  a.kind = kind;
  a.code = code;
  a.reason = std::move(reason);
  return a;
}

std::string boundaries(int n) { return fmt::format("{} {}", n, n == 1 ? "boundary" : "boundaries"); }

}  // namespace

Applicability assess_applicability(const AnalyzedSurface& surface) {
  const TopologyReport& r = surface.report;
  const TriangleSoup& soup = surface.soup;
  const auto bad = [](std::string reason) {
    return refuse(SurfaceCase::invalid, ErrorCode::bad_input, std::move(reason));
  };
  if (r.faces == 0) return bad("no triangles: the file holds no surface");
  if (!r.nonfinite_vertices.empty())
    return bad(fmt::format("{} has a non-finite coordinate ({} such vertices)",
                           describe_vertex(soup, r.nonfinite_vertices.front()),
                           r.nonfinite_vertices.size()));
  if (r.range.largest_magnitude > kMaxCoordinate)
    return bad(fmt::format("{} has a coordinate of {:.3g}: quadmesh computes with coordinates up to {:.0e} "
                           "in size; scale the model",
                           describe_vertex(soup, r.range.largest_vertex), r.range.largest_magnitude,
                           kMaxCoordinate));
  if (r.range.largest_vertex >= 0 && r.range.diagonal < kMinModelSize)
    return bad(fmt::format("the model is {:.3g} across (bounding-box diagonal): quadmesh computes with "
                           "models at least {:.0e} across; scale the model",
                           r.range.diagonal, kMinModelSize));
  if (r.range.largest_magnitude > kMaxOffsetRatio * r.range.diagonal)
    return bad(fmt::format("{} is {:.3g} from the origin, more than {:.0e} times the model's size ({:.3g}): "
                           "its coordinates lose the digits of its edges there; move the model near the "
                           "origin",
                           describe_vertex(soup, r.range.largest_vertex), r.range.largest_magnitude,
                           kMaxOffsetRatio, r.range.diagonal));
  if (!r.repeated_corner_faces.empty())
    return bad(fmt::format("{} uses a vertex twice ({} such triangles)",
                           describe_triangle(soup, r.repeated_corner_faces.front()),
                           r.repeated_corner_faces.size()));
  if (!r.duplicate_faces.empty())
    return bad(fmt::format("{} repeats the vertices of an earlier triangle ({} duplicates)",
                           describe_triangle(soup, r.duplicate_faces.front()),
                           r.duplicate_faces.size()));
  if (!r.nonmanifold_edges.empty()) {
    const auto& e = r.nonmanifold_edges.front();
    return bad(fmt::format("non-manifold edge between {} and {}: {} triangles share it ({} such edges)",
                           describe_vertex(soup, e.a), describe_vertex(soup, e.b), e.triangles,
                           r.nonmanifold_edges.size()));
  }
  if (!r.nonmanifold_vertices.empty())
    return bad(fmt::format(
        "non-manifold {}: the surface is pinched there, its triangles form separate fans ({} such "
        "vertices)",
        describe_vertex(soup, r.nonmanifold_vertices.front()), r.nonmanifold_vertices.size()));
  if (!r.zero_area_faces.empty())
    return bad(fmt::format("{} has zero area: its vertices are collinear ({} such triangles)",
                           describe_triangle(soup, r.zero_area_faces.front()),
                           r.zero_area_faces.size()));
  if (r.components.count > 1)
    return refuse(SurfaceCase::several_components, ErrorCode::unsupported,
                  fmt::format("{} connected components (the largest has {} of {} triangles): mesh "
                              "one surface at a time, or keep the largest (largest_component())",
                              r.components.count,
                              r.components.triangle_counts[r.components.largest()], r.faces));
  if (!r.orientation.orientable)
    return refuse(SurfaceCase::non_orientable, ErrorCode::unsupported,
                  fmt::format("the surface is non-orientable (like a Möbius strip): orientation "
                              "contradicts itself at the edge between {} and {}",
                              describe_vertex(soup, r.nonorientable_edge[0]),
                              describe_vertex(soup, r.nonorientable_edge[1])));

  const int g = r.genus;
  const int n = r.boundary_loop_count();
  const long chi = r.euler_characteristic;
  const std::string shape =
      n == 0 ? fmt::format("closed surface of genus {}, chi = {}", g, chi)
             : fmt::format("genus {} with {}, chi = {}", g, boundaries(n), chi);
  if (chi > 0) {
    const bool disk = n > 0;
    return refuse(disk ? SurfaceCase::disk : SurfaceCase::sphere, ErrorCode::unsupported,
                  fmt::format("{}: not supported: a {} carries no holomorphic 1-form (its {} is a "
                              "sphere); the method needs at least two boundaries or a handle",
                              shape, disk ? "disk" : "sphere",
                              disk ? "doubled surface" : "surface itself"));
  }
  Applicability a;
  a.supported = true;
  a.code = ErrorCode::bad_input;
  if (n == 0) {
    a.kind = SurfaceCase::closed;
    a.doubled_genus = g;
    a.reason = fmt::format("{}: supported; no doubling needed, the forms live on the surface "
                           "itself (genus {})",
                           shape, g);
  } else {
    a.doubled_genus = 2 * g + n - 1;
    a.kind = chi == 0 ? SurfaceCase::annulus : SurfaceCase::open_negative;
    a.reason = fmt::format("{}: supported; the doubled surface has genus {}{}", shape,
                           a.doubled_genus,
                           chi == 0 ? " (an annulus: a singularity-free grid)" : "");
  }
  return a;
}

void require_supported(const AnalyzedSurface& surface) {
  const Applicability a = assess_applicability(surface);
  if (!a.supported)
    throw Error(a.code, a.reason, a.kind == SurfaceCase::several_components ? "largest_component()" : "");
}

AnalyzedSurface largest_component(const AnalyzedSurface& surface) {
  const Components& comps = surface.report.components;
  if (comps.count <= 1) return surface;
  return analyze_topology(sub_soup(surface.soup, comps.triangles_of(comps.largest())));
}

}  // namespace qm
