// One meshing attempt: everything after the forms (method.md sections 5-9) for
// one choice of h and of its scale. The forms are computed once (form_setup.h);
// an attempt costs a fraction of them, so the retry policy (retry_policy.h) can
// make several and the ranking (candidate_ranking.h) keep the best.
#pragma once

#include "libquadmesh/pipeline/internal/candidate_ranking.h"
#include "libquadmesh/pipeline/internal/retry_policy.h"
#include "libquadmesh/pipeline/internal/stages.h"
#include "libquadmesh/pipeline/mesh_quads.h"

#include <vector>

namespace qm {

/// What every attempt on one triangulation of S starts from.
struct FormSetup {
  TriangleSoup soup;              ///< S as the forms were computed on it (chords split, perhaps remeshed)
  std::vector<FaceMap> basis;     ///< the symmetric forms h_k on `soup`
  NamedLoops loops;              ///< the loops the quantization rounds, on `soup`
  double area = 0;                ///< of the input as given (before remeshing and chord splits)
  double diagonal = 0;            ///< of the input's bounding box (as given)
  /// The result's fields every attempt shares: remeshing, forms, requested size,
  /// the chosen coefficients and boundary tips.
  QuadMeshResult preamble;
  /// Auto's form without the zeros at the boundary tips, when it has some (else empty).
  Eigen::VectorXd free_coefficients;
  bool forms_computed = false;    ///< `basis` and `loops` are set (form_setup.h compute_forms)
};

/// The loops of H_1(S) whose periods the quantization rounds (forms/named_loops.h).
NamedLoops period_loops(const TriangleSoup& soup);

/// Drops points no quad uses (corners of dropped cells).
void compact(LatticeQuads& q);

/// Per quad point, the boundary loop of S it lies on (by `loops`' numbering, as the
/// output's boundary groups count them), or -1.
std::vector<int> boundary_loop_of_points(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                         const NamedLoops& loops, const LatticeQuads& quads);

/// Counts (and locates the first of) the quads' boundary points off S's boundary
/// (QuadMeshResult::stray_boundary_points, first_stray_point).
void note_stray_boundary(QuadMeshResult& r);

/// Meshes `setup.soup` with the form and scale of `request`: scale, zeros at
/// vertices, cone stars refined, quantization, untangling, extraction. The result
/// is complete (its surface is S as meshed) and measured once (assess_candidate).
/// Throws qm::Error(solver) when the quantization cannot be solved.
Candidate mesh_attempt(const FormSetup& setup, const QuadMeshOptions& options, const AttemptRequest& request,
                       Stages& stages);

}  // namespace qm
