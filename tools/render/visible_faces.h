// Hidden faces removed: which faces of a mesh show in a picture, and the order
// to paint them in.
#pragma once

#include "tools/render/view.h"

#include <vector>

namespace qm::tools {

/// A face as the picture draws it.
struct DrawnFace {
  int face = -1;              ///< index in mesh.faces
  std::vector<Vec2> corners;  ///< picture coordinates, in the face's order
  double depth = 0;           ///< depth of its centroid along the view (larger: nearer)
  double facing = 0;          ///< unit normal . toward_viewer in [-1, 1]; < 0: its back shows
};

/// The faces of `mesh` that show in the picture of `frame`, farthest first
/// (painter's order: each face is drawn over the ones behind it). Visibility is
/// decided on a depth buffer over the drawing with `samples_per_pixel`^2 samples
/// per pixel: every face (fan-split from its first corner) is rasterized at the
/// sample centres, and a face shows when it is the nearest at one sample at least.
/// So faces hidden behind nearer ones, faces seen edge-on and faces smaller than
/// a sample are left out. Front and back faces alike are kept (an open surface
/// shows its back where it turns away).
std::vector<DrawnFace> visible_faces(const PolygonMesh& mesh, const View& view, const Frame& frame,
                                     int samples_per_pixel = 2);

}  // namespace qm::tools
