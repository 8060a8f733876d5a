// Before any attempt (method.md sections 1-4): the size the options ask for, the
// remeshing when the forms need it, the symmetric forms, and the choice of h.
#pragma once

#include "libquadmesh/pipeline/internal/attempt.h"
#include "libquadmesh/pipeline/internal/stages.h"
#include "libquadmesh/pipeline/mesh_quads.h"

namespace qm {

/// The edge length the options ask for.
struct RequestedSize {
  double size = 0;  ///< QuadMeshOptions::size, or size_relative x the bounding-box diagonal, or
                    ///< 1/default_size_divisions of it (QuadMeshResult::size_requested)
  double edge = 0;  ///< what the quads should measure: with QuadMeshOptions::quads, the edge of a
                    ///< square of area / quads; else `size`
};

/// Without a size, the quads measure this fraction of the bounding-box diagonal (1/60).
inline constexpr double default_size_divisions = 60.0;

RequestedSize requested_size(const TriangleSoup& soup, const QuadMeshOptions& options);

/// Throws qm::Error(bad_input) naming QuadMeshOptions::max_quads when the options
/// imply more quads than it allows (implied_quad_count, mesh_quads.h).
void require_within_work_limit(const TriangleSoup& soup, const QuadMeshOptions& options);

/// The surface before any form: its area, diagonal and requested size, remeshed
/// first when asked (RemeshPolicy::always), its boundary chords split, and the
/// doubled surface's genus (1 - chi, `topology` the soup's: topology_of); the
/// forms' residuals NaN (not computed). What the cone route needs: a cone route
/// kept first never computes the forms (bunny-open: 1.8 s of its 13).
FormSetup prepare_surface(TriangleSoup soup, SurfaceTopology topology, const QuadMeshOptions& options,
                          Stages& stages);

/// The symmetric forms on setup.soup, remeshed first when the input's forms are
/// inaccurate (RemeshPolicy::automatic), the loops the quantization rounds, and
/// the coefficients of h the options ask for (QuadMeshOptions::coefficients,
/// ::form); auto's are chosen by choose_form. Returns whether it remeshed (the
/// soup is then another). Throws qm::Error(bad_input) naming the option when
/// coefficients or form do not fit the surface.
bool compute_forms(FormSetup& setup, const QuadMeshOptions& options, Stages& stages);

/// prepare_surface, then compute_forms.
FormSetup prepare_forms(TriangleSoup soup, const QuadMeshOptions& options, Stages& stages);

/// Auto's coefficients of h, where prepare_forms set none: the most uniform form,
/// with zeros at the boundary tips (and the one without them in
/// FormSetup::free_coefficients). Only the Abel route needs them: a cone route
/// kept first never chooses (bunny-open: 0.4 s).
void choose_form(FormSetup& setup, const QuadMeshOptions& options, Stages& stages);

}  // namespace qm
