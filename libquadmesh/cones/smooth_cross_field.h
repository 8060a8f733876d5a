// The smoothest boundary-aligned cross field (method.md section 11, the
// alternative cone placement): its singularities are the interior cones, the
// classical route of QuadWild and Gmsh's quasi-structured quads.
//
// A cross (four directions a quarter turn apart) on triangle f is stored as its
// fourth power psi_f = e^(4 i theta) in the triangle's local frame
// (face_geometry.h), so the four directions are one complex number. Across an
// inner edge the frames of f and its twin g differ by the angle t_fg between the
// edge's directions in the two frames (the discrete Levi-Civita connection);
// the field's roughness is
//   E(psi) = sum over inner edges  w_e |psi_g - e^(4 i t_fg) psi_f|^2,
// w_e = |e|^2 / (area_f + area_g) (scale free) [Knoeppel, Crane, Pinkall,
// Schroeder, Globally Optimal Direction Fields, 2013]. Triangles with a boundary
// edge hold the cross along that edge (the longest when two); E is minimized over
// the others: one sparse Hermitian solve. (Knoeppel et al.'s eigenproblem is the
// field with no alignment; with the boundary held it is this linear system, so no
// eigensolver is used.) The minimizer's |psi| sags and merges singularities (a
// disk's four into one of index 1): steps of diffusion over the quad size, each
// after making the crosses unit, spread them again (CrossFieldOptions).
//
// The index at an inner vertex: going around it through its triangles, the jumps
// arg(psi_g / (e^(4 i t_fg) psi_f)) add up, with 4 times the angle defect (the
// connection's own turn around the vertex), to 2 pi m: m quarter turns, a cone
// where the quad mesh has 4 - m quads.
#pragma once

#include "libquadmesh/cones/cone_set.h"

#include <complex>
#include <vector>

namespace qm {

struct SmoothCrossField {
  /// per triangle, psi_f (|psi_f| <= 1; small near a singularity)
  std::vector<std::complex<double>> psi;
  /// per triangle, 1 when a boundary edge holds its cross
  std::vector<char> held;
  /// per vertex, the field's index in quarter turns (0 on the boundary)
  std::vector<int> index;
};

struct CrossFieldOptions {
  /// The scale (model units) at which singularities stay apart: the diffusion
  /// time of each step is length^2. The quad edge is the natural choice.
  double length = 1.0;
  /// Diffusion-and-normalization steps after the linear minimizer (0: none).
  int diffusion_steps = 20;
  /// Per vertex, the quads each boundary vertex is to be in (quads_per_vertex of
  /// the corners' cones); empty: the field's own choice. Going round a boundary
  /// vertex of angle a in q quads, the cross turns by a - q pi/2 against the
  /// surface; left to itself it turns by the least such angle, so a corner near
  /// half-way between two counts (135, 225 degrees) may get the other one, and the
  /// interior singularities then carry a quarter turn more or less than the
  /// corners leave. Where q is not the nearest count, or nearly not
  /// (corner_hold_margin), the crosses of the vertex's triangles are held, turning
  /// by a - q pi/2 from one boundary edge to the other in equal steps (a vertex in
  /// m triangles: m + 1 steps, each unambiguous while below pi/4).
  std::vector<int> boundary_quads;
  /// Radians: a count within this of half-way is held too.
  double corner_hold_margin = 0.1;
};

/// Precondition: an oriented, connected soup with at least one boundary loop.
SmoothCrossField smooth_cross_field(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                    const CrossFieldOptions& options = {});

/// The field's singularities as cones: {v, 4 - index(v)} at every inner vertex
/// whose index is not 0.
std::vector<Cone> field_singularities(const SmoothCrossField& field);

}  // namespace qm
