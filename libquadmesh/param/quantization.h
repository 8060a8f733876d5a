// The quantized, seamless, boundary-aligned parameterization (method.md
// section 7, "beyond the paper"; integration as in section 8).
//
// Given the target map T = s h (a closed form as a FaceMap, orientation kept) it
// computes the map Phi = U + iV that is closest to T in the L2 (Dirichlet) sense,
//   minimize  sum_f  integral_f |grad Phi - grad T|^2,
// among the maps that satisfy, with integers everywhere:
//  1. periods: the U- and V-periods of the handle loops and the U-periods of the
//     boundary loops 1..n-1 are integers (not rounded to 0 when |p| > 1/4);
//  2. V is constant on every boundary loop, with integer differences between
//     loops (the V-integral of each bridge path is rounded, same rule);
//  3. every zero is a lattice point (U and V integers; a boundary zero needs U);
//  +  sharp boundary corners (zero_stars.h) have integer U; a corner that would
//     land on the lattice point of the cone before it along its loop stays free.
// How: Phi = psi + Xi, with xi = T + sum_k e_k Re(h_k) + i d_k Im(h_k) a closed
// form whose periods are exactly the rounded integers (e and d solve the small
// period systems; Im(h_k) vanishes on the boundary, so V stays constant there),
// Xi its integral on the surface cut into a disk (faces joined along a
// breadth-first spanning tree, Xi = 0 at the first vertex of boundary 0), and psi
// a single-valued function found by one sparse Cholesky solve per component with
// Dirichlet values at the constrained vertices. Transitions across cut edges are
// translations by the periods of xi (integers). Around a zero z the star is fixed
// to the local model Phi(z) + a w^g, w the star flattened with intrinsic polar
// coordinates and g = image angle / 3D angle sum (a fitted to xi, real on the
// boundary), fold-free by construction (see zero_stars.h); the rest of a disk of
// image radius 3/4 cell blends from the model (projected on the tangent plane) into
// xi translated with the zero. Around a corner the whole disk is xi translated.
#pragma once

#include "libquadmesh/forms/named_loops.h"
#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/param/zero_stars.h"

#include <string>

namespace qm {

struct LoopPeriod {
  std::string loop;  ///< "handle_0", "boundary_1", "bridge_1" ...
  Complex before;    ///< period of T (bridges: the V-integral only, as the imaginary part)
  Complex after;     ///< the integers imposed
};

struct Quantization {
  FaceMap param;                    ///< Phi per triangle corner on the cut surface
  std::vector<LoopPeriod> periods;  ///< what was rounded, before and after
  std::size_t lattice_zeros = 0;    ///< zeros put on lattice points
  std::size_t corners = 0;          ///< corners put on lattice points
  std::size_t corners_dropped = 0;  ///< corners left free to avoid a collision
  std::size_t fixed_vertices = 0;   ///< Dirichlet vertices of U and V together
  /// sum_f int |grad Phi - grad T|^2 / sum_f int |grad T|^2: the distortion the
  /// rounding added.
  double distortion = 0;
  std::size_t flipped = 0;  ///< triangles with a non-positive image area
};

/// Precondition: `soup` has boundary, `target` is closed and orientation-keeping,
/// `basis` are the symmetric forms h_k on the same triangles (their real parts span
/// H^1(S), their imaginary parts vanish on the boundary), zeros are vertices with
/// refined stars; `cones` holds the zeros and the corners. Throws qm::Error(solver) if a factorization fails.
Quantization quantize(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                      const FaceMap& target, const std::vector<FaceMap>& basis,
                      const std::vector<ZeroVertex>& cones, const NamedLoops& loops);

/// Round to the nearest integer, but away from 0 when |x| > 1/4 (rule 4: a period
/// that was not 0 must not collapse).
double round_nonzero(double x);

/// Integer boundary levels (rule 2 with rule 4): the least squared rounding in
/// which levels more than 1/4 apart stay distinct and in the same order (a strip
/// between two boundaries must not collapse), shifted by an integer so that
/// levels[0] keeps its own rounding.
std::vector<double> round_levels(const std::vector<double>& levels);

/// The integral of a closed form along a vertex path (closed: back to the start).
Complex path_integral(const SurfaceAdjacency& adjacency, const FaceMap& form,
                      const std::vector<int>& path, bool closed);

/// Integrates a closed form over the surface cut into a disk: faces are joined
/// along a breadth-first spanning tree from the first triangle at `base`, where the
/// result is 0.
FaceMap integrate_cut(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& form,
                      int base);

}  // namespace qm
