// Acute corners, the map's shape: the seamless map fits the cone metric's scaled
// frame, a conformal target (a rotation and a scale per triangle). Near a tip of
// angle a on S that its quads open to a right angle, that frame turns by
// 90 degrees - a across the tip's few triangles, which no map's gradient follows:
// the fit shrinks there and the tip's own quad comes out several times the size (a
// 30-degree tip: 4 x). A quad mesh made by hand shears the lattice at such a tip
// instead: the tip's quad a parallelogram of angle a whose sides run along the two
// boundary edges. Near each acute tip (tip_scale.h) the fit asks for that affine
// map: its two edges to the two lattice axes at the metric's scale.
#pragma once

#include "libquadmesh/cones/cross_field.h"
#include "libquadmesh/cones/tip_scale.h"
#include "libquadmesh/param/face_map.h"

#include <vector>

namespace qm {

/// The full shear within this share of the shear's reach from the tip, fading to
/// none at the reach...
constexpr double full_shear_share = 0.5;
/// ...which is this many quads, or the tip's reach (AcuteTip::reach) when less.
constexpr double shear_radius_quads = 6.0;

/// Per triangle, the shape the fit asks of the map's gradient beside the cone
/// metric's scaled frame c_f = e^(u_f - i angle_f) / size: dW(x) = c_f (conformal_f
/// x + anticonformal_f conj(x)) for a vector x in the triangle's local frame
/// (face_geometry.h). 1 and 0 (the frame itself) away from the tips.
struct FitShape {
  std::vector<Complex> conformal;
  std::vector<Complex> anticonformal;
};

/// The shape near `tips`: in a triangle within the reach, the affine map that
/// takes the tip's two boundary edges (their directions in the triangle's plane)
/// to the lattice axes the field's chart gives them, each at the frame's scale,
/// blended with the frame by the triangle's distance from the tip (full within
/// full_shear_share of the reach, none at it). Triangles where the edges'
/// directions do not make a wedge in the triangle's plane keep the frame.
FitShape tip_shear(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<AcuteTip>& tips,
                   const CrossField& field, double size);

}  // namespace qm
