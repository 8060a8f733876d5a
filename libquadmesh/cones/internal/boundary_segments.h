// The boundary of a seamless map between its corner cones: each run of boundary
// edges from one corner to the next is a straight lattice line in the map, whose
// length (in quads) is the difference of the two lines across its ends once both
// are integer. Quantization must not round that length to zero: two corners on one
// lattice point fold the map there (kitten's coarse hole polygons: a 104-degree and
// a 264-degree corner 0.6 quads apart).
#pragma once

#include "libquadmesh/cones/cross_field.h"
#include "libquadmesh/cones/cut_graph.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace qm {

/// One boundary edge as the map sees it: its end wedges, the coordinate that runs
/// along it (0: Re, 1: Im) and the sign that makes its target image run forward.
struct SegmentEdge {
  int wedge_from = -1;
  int wedge_to = -1;
  int along = 0;
  double sign = 1;
};

/// The boundary edges grouped from corner to corner (boundary vertices whose quads
/// differ from 2). Loops without a corner are left out.
struct BoundarySegments {
  std::vector<std::vector<SegmentEdge>> segments;
  std::vector<double> target_length;  ///< the length the fit aims at (quads)
};

/// `scale` per triangle: the complex factor taking its local frame to the map's
/// target (e^u / size turned by the field), as the seamless map's fit uses.
BoundarySegments boundary_segments(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                   const CrossField& field, const CutGraph& cut, const std::vector<int>& quads,
                                   const std::vector<Complex>& scale);

/// The signed length of segment s for the unknowns z (two per wedge: Re, Im).
double segment_length(const BoundarySegments& segments, std::size_t s, const Eigen::VectorXd& z);

/// Segments whose length is a whole number below 1 (both lines across their ends
/// integer and on one lattice point, or crossed): the map folds at their corners.
std::size_t collapsed_segments(const BoundarySegments& segments, const Eigen::VectorXd& z);

/// A segment whose target is under this many quads is one the map may hold to one
/// quad (seamless_map.h, `hold_short_segments`): its nearest whole length, 1, for
/// one under 1.5, and never 0, which folds the map.
constexpr double short_segment_length = 1.5;

/// The segments whose target length is under short_segment_length, in order.
std::vector<std::size_t> short_segments(const BoundarySegments& segments);

/// Segment s's signed length (segment_length) as a sum of coefficient x unknown,
/// one term per unknown that remains (a wedge shared by two edges cancels).
std::vector<std::pair<int, double>> segment_terms(const BoundarySegments& segments, std::size_t s);

}  // namespace qm
