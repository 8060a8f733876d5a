// Which vertices of a quad mesh are irregular, one by one: the vertices that
// QuadQuality::irregular_interior and irregular_boundary count.
//
// The quality module (libquadmesh/quality/quad_quality.h) gives the counts only;
// the picture needs the vertices themselves. The definition is the quality
// module's, and a test holds the two to the same counts on every test mesh.
#pragma once

#include "libquadmesh/quality/quad_quality.h"

#include <vector>

namespace qm::tools {

struct IrregularVertex {
  int vertex = -1;        ///< point index
  int valence = 0;        ///< interior: edges at the vertex; boundary: faces at it
  int regular = 4;        ///< what a regular grid has there (boundary: from its angle)
  bool boundary = false;  ///< on a boundary edge (an edge of one face)
};

/// The irregular vertices of `mesh`, by increasing index: interior vertices with a
/// number of edges other than 4, and boundary vertices whose face count is not
/// max(1, round(corner angle sum / 90 degrees)) (QuadQuality's definitions;
/// corner angles by corner_angle_deg). Points no face uses are skipped.
std::vector<IrregularVertex> irregular_vertices(const PolygonMesh& mesh);

}  // namespace qm::tools
