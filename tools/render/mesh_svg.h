// A picture of a surface mesh (quads and triangles) as a self-contained SVG
// document: the faces that show from the view, shaded and coloured by a quality
// figure, the singular vertices marked by valence, a colour legend and a caption
// with the counts (`quadmesh render`, and the meshes of `quadmesh compare`).
#pragma once

#include "libquadmesh/quality/quad_quality.h"
#include "tools/render/face_coloring.h"
#include "tools/render/view.h"

#include <string>

namespace qm::tools {

struct MeshPictureOptions {
  FaceColoring coloring = FaceColoring::scaled_jacobian;
  double size = 0;         ///< reference length of FaceColoring::size (> 0 for it)
  std::string size_label;  ///< how the caption names that length ("--size 1.5%"); "" shows the number
  std::string title;       ///< the first line (the file's name)
  double width = 640;      ///< the drawing's width in px (the legend is beside it)
  double max_height = 560;  ///< the drawing's largest height in px
};

/// The picture's parts, for callers and tests that need them without parsing.
struct MeshPicture {
  std::string svg;               ///< the document
  std::size_t faces_drawn = 0;   ///< one <polygon> per face that shows
  std::size_t marked = 0;        ///< one <circle> per interior irregular vertex that shows
};

/// The picture of `mesh` seen along `view` in `frame` (frame.left and frame.top
/// are set here: the drawing goes below the title). `quality` is quad_quality of
/// the same mesh: the caption's counts and figures are its fields. Faces are
/// visible_faces's (hidden ones left out, painted farthest first), each filled
/// with its face_values colour on color_scale(options.coloring), darkened by
/// 0.55 + 0.45 |cos| of its normal to the view (a headlight) and greyed where its
/// back shows; their edges are drawn unless the median edge is under 2.5 px on
/// screen (the caption says so). Interior irregular vertices (irregular_vertices) on a face that
/// shows get a circle filled by valence: 3 black, 5 white, 6 and more magenta,
/// 2 and less green; each circle carries data-vertex (the point index) and
/// data-valence. Irregular boundary vertices are counted in the caption, not
/// marked. Text is XML-escaped.
MeshPicture mesh_picture(const PolygonMesh& mesh, const QuadQuality& quality, const View& view, Frame frame,
                         const MeshPictureOptions& options);

}  // namespace qm::tools
