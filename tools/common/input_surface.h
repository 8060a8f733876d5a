// The first steps every quadmesh command shares: read a file, analyse its
// topology, optionally keep the largest component.
#pragma once

#include "io/read_surface.h"
#include "libquadmesh/topology/applicability.h"
#include "tools/common/progress.h"

namespace qm::tools {

struct InputSurface {
  io::SurfaceFile file;       ///< as read (its soup moved into `surface`)
  AnalyzedSurface surface;    ///< analysed (and reduced, with largest_component)
  std::size_t dropped_components = 0;
};

/// The surface's area (the sum of its triangles'): the work limits' estimates.
double total_area(const TriangleSoup& soup);

/// Reads and analyses `path`, reporting stages on `progress`. Throws qm::Error
/// for unreadable files; topology verdicts are left to the caller.
InputSurface load_input_surface(const std::string& path, const io::ReadOptions& read,
                                bool largest_only, const Progress& progress);

}  // namespace qm::tools
