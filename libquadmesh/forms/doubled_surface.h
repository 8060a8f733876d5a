// The doubled surface D = S+ U S- and its involution phi (method.md section 1,
// seed paper Alg. 4.1).
//
// S- is a copy of S with reversed face orientation; boundary vertices are shared,
// so D is closed. phi swaps v+ and v-, fixes boundary vertices and boundary edges
// pointwise, and maps face f+ to f-. It reverses orientation and is an isometry.
// Conventions: vertex v < |V(S)| and face f < |F(S)| of D are vertex v and face f
// of S (the + copy). Edge values of 1-forms are stored along halfedge(e, 0).
#pragma once

#include "libquadmesh/core/mesh.h"

#include <vector>

namespace qm {

struct DoubledSurface {
  Mesh mesh;                       ///< D, closed
  std::size_t input_vertices = 0;  ///< |V(S)|: vertices 0..input_vertices-1 are S+
  std::size_t input_faces = 0;     ///< |F(S)|: faces 0..input_faces-1 are S+
  std::vector<int> vertex_mirror;  ///< phi on vertices
  std::vector<int> face_mirror;    ///< phi on faces
  std::vector<int> edge_mirror;    ///< phi on edges
  /// +1 when phi maps halfedge(e, 0) onto halfedge(phi(e), 0), -1 when onto its
  /// opposite: (phi* w)(e) = edge_mirror_sign[e] * w(phi(e)).
  std::vector<int> edge_mirror_sign;
  std::vector<char> is_input_boundary_edge;  ///< the edge is a boundary edge of S (fixed by phi)

  bool is_plus_face(int f) const { return static_cast<std::size_t>(f) < input_faces; }
};

/// Doubles a surface with boundary. Precondition: `surface` is a valid
/// Surface_mesh with at least one border. |V(D)| = 2|V| - |V_boundary|.
DoubledSurface double_surface(const Mesh& surface);

/// The trivial "doubling" of a closed surface: D = S, phi = identity. The
/// symmetric forms of a closed surface are all its holomorphic forms.
DoubledSurface identity_double(const Mesh& closed_surface);

}  // namespace qm
