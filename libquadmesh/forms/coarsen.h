// A working triangulation for inputs far finer than the quads (issue 21). The map
// is linear on each triangle, so triangles a fraction of a quad wide are all the
// forms, the quantization and the extraction need; a scan of a million triangles
// meshed at 1.5% of its diagonal carries 50 to 250 of them per quad, and every
// stage pays for them. Coarsening by half-edge collapses [Hoppe 1996; the link
// condition of Dey et al. 1999] keeps a subset of the input's own points (each
// still on S, with its file label), the topology, the corners of the boundary and
// the creases, so the working surface is inscribed in S to within the sagitta of
// its edges.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <cstddef>

namespace qm {

struct CoarsenOptions {
  /// Edges shorter than this are collapsed (the target edge length L).
  double edge_length = 0;
  /// No collapse makes an edge longer than this multiple of L.
  double max_edge_factor = 1.6;
  /// No collapse turns a triangle's normal by more than this (degrees): a crease
  /// or a bend sharper than it per edge stays. (bunny-open-large at a working edge
  /// L of 0.5% of its diagonal: 10 degrees leave it within 0.13 L of the scan, 20
  /// within 0.28 L, 5 within 0.07 L, with 1.6% and 3.2% more triangles than 20.)
  double max_normal_turn_deg = 10.0;
  /// A boundary point is removed only where the boundary turns by less than this
  /// (degrees) and lies within boundary_tolerance x L of the new boundary edge.
  double max_boundary_turn_deg = 20.0;
  double boundary_tolerance = 0.02;
  /// No collapse leaves a triangle whose shape quality (4 sqrt(3) area / sum of
  /// squared edges: 1 equilateral, 0 degenerate) is below this and below the
  /// worst one it replaces.
  double min_quality = 0.25;
};

struct CoarsenReport {
  std::size_t collapses = 0;
  int passes = 0;
  bool topology_kept = true;  ///< false: the result would have changed chi or the boundary; the input is returned
};

/// The input with short edges collapsed, shortest first, in passes until no edge
/// shorter than options.edge_length can go. Every point of the result is a point
/// of the input (coordinates and label); every triangle keeps the label of the
/// input triangle whose slot it took. CAD curve edges are dropped (callers coarsen
/// discrete inputs); the physical groups are kept. Precondition: an oriented manifold
/// soup with boundary; options.edge_length > 0. Deterministic (no threads).
TriangleSoup coarsen(const TriangleSoup& soup, const CoarsenOptions& options, CoarsenReport* report = nullptr);

}  // namespace qm
