// Whether the symmetric-differential method applies to a surface, and why not
// (method.md section 0).
//
// Holomorphic 1-forms exist on the doubled surface when its genus
// G = 2g + n - 1 (n >= 1 boundaries) or G = g (closed) is at least 1, that is
// chi <= 0 for a connected orientable manifold surface.
#pragma once

#include "libquadmesh/core/error.h"
#include "libquadmesh/topology/topology_report.h"

#include <string>

namespace qm {

enum class SurfaceCase {
  invalid,          ///< bad input: see the reason
  several_components,
  non_orientable,
  disk,             ///< chi = 1: no holomorphic 1-form
  sphere,           ///< chi = 2: no holomorphic 1-form
  annulus,          ///< chi = 0, two boundaries: singularity-free grid
  open_negative,    ///< chi < 0 with boundary: the seed paper's case
  closed,           ///< no boundary, genus >= 1: forms on the surface itself
};

struct Applicability {
  bool supported = false;
  SurfaceCase kind = SurfaceCase::invalid;
  ErrorCode code = ErrorCode::bad_input;  ///< meaningful when not supported
  std::string reason;                     ///< one line, for users (supported or not)
  int doubled_genus = -1;                 ///< genus of the surface the forms live on
};

/// The verdict, first defect first: bad input (empty, non-finite, degenerate,
/// duplicate, non-manifold), then unsupported (several components,
/// non-orientable, chi > 0), else supported with a summary in words.
Applicability assess_applicability(const AnalyzedSurface& surface);

/// Throws qm::Error (code and reason from assess_applicability) unless supported.
void require_supported(const AnalyzedSurface& surface);

/// The surface reduced to its largest connected component, analysed again.
AnalyzedSurface largest_component(const AnalyzedSurface& surface);

}  // namespace qm
