// Ligaments: where two boundary lines of a seamless map face each other across a
// strip under about a quad wide (a shank's side and a lightening hole in it, a rim
// and a wheel's holes, a ring round a bore). Their distance in the map is the
// difference of the two lines once both are integer, and quantization must not
// round it to zero: the strip then has no quads, the map folds across it and the
// quads part the surface in two (a link's shank at 2% of the diagonal, its hole
// 0.68 quads from each side: chi 0 against -2). boundary_segments.h keeps a corner
// apart from the next one along one loop; this keeps one loop apart from another.
#pragma once

#include "libquadmesh/cones/cross_field.h"
#include "libquadmesh/cones/cut_graph.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <vector>

namespace qm {

/// Two boundary lines facing each other in one chart: the unknowns (a wedge's
/// coordinate across each line, in z's layout: two per wedge) whose difference is
/// the strip's width, and the sign that makes the width of the continuous map
/// positive.
struct Ligament {
  int line_from = -1;
  int line_to = -1;
  double sign = 1;
};

/// Pairs of straight boundary vertices (2 quads) joined by one edge, or by two
/// through a vertex whose corners lie in one chart, on different loops or far apart
/// along one, whose boundary lines run along the same coordinate there: each pair
/// of lines once. Their widths are not known yet (sign 1).
std::vector<Ligament> facing_boundary_lines(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                            const CrossField& field, const CutGraph& cut,
                                            const std::vector<int>& quads);

/// The pairs whose width in z (a map before quantization) lies between
/// `min_width` and `max_width` quads, each with the sign of that width.
std::vector<Ligament> narrow_ligaments(const std::vector<Ligament>& facing, const Eigen::VectorXd& z,
                                       double min_width, double max_width);

/// Ligaments whose two lines are integer in z and less than a quad apart (on one
/// lattice line, or crossed).
std::size_t collapsed_ligaments(const std::vector<Ligament>& ligaments, const Eigen::VectorXd& z);

}  // namespace qm
