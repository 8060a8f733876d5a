// Adjacency of an oriented manifold triangle soup with boundary: the faces around
// each vertex in counter-clockwise order, directed edges, boundary loops.
// Rebuilt after every refinement; the param/ and extract/ stages share it.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/param/face_map.h"

#include <vector>

namespace qm {

/// Where a directed edge a->b sits: triangle f, with a at corner i and b at corner j.
struct EdgeCorner {
  int face = -1;
  int i = -1;
  int j = -1;
};

struct SurfaceAdjacency {
  const TriangleSoup* soup = nullptr;          ///< the soup described (must outlive this)
  std::vector<std::vector<int>> vertex_faces;  ///< faces at each vertex (any order)
  std::vector<char> boundary_vertex;
  /// Boundary loops, each in the direction of its triangles (the surface on the left).
  std::vector<std::vector<int>> boundary_loops;
  std::vector<int> loop_of_vertex;  ///< boundary loop of a boundary vertex, else -1

  /// The triangle holding the directed edge a->b, or face -1 (a scan of a's faces).
  EdgeCorner find(int a, int b) const {
    for (int f : vertex_faces[static_cast<std::size_t>(a)]) {
      const Triangle& t = soup->triangles[static_cast<std::size_t>(f)];
      for (int i = 0; i < 3; ++i)
        if (t[i] == a && t[(i + 1) % 3] == b) return EdgeCorner{f, i, (i + 1) % 3};
    }
    return EdgeCorner{};
  }
  bool is_boundary_edge(int a, int b) const {
    return (find(a, b).face < 0) != (find(b, a).face < 0);
  }
};

/// Precondition: an oriented, edge- and vertex-manifold soup.
SurfaceAdjacency surface_adjacency(const TriangleSoup& soup);

/// V - E + F of the soup described by `adjacency` (the points no triangle uses
/// left out).
int euler_characteristic(const SurfaceAdjacency& adjacency);

/// Whether the surface has handles: genus (2 - chi - boundary loops) / 2 > 0.
bool has_handles(const SurfaceAdjacency& adjacency);

/// The neighbours of v in counter-clockwise order (for a boundary vertex, from the
/// boundary neighbour that follows v on its loop... to the one that precedes it),
/// with the face between neighbour k and k + 1.
struct VertexRing {
  std::vector<int> neighbours;
  std::vector<int> faces;  ///< faces[k] holds v, neighbours[k], neighbours[k + 1 (mod)]
  bool boundary = false;
};
VertexRing vertex_ring(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, int v);

/// The 3D corner angle at v of each face of its ring: angles[k] lies between
/// neighbours[k] and neighbours[k + 1] (ring.faces.size() values).
std::vector<double> ring_angles(const TriangleSoup& soup, const VertexRing& ring, int v);

/// The value of a closed form (a FaceMap) along the directed edge a->b: the
/// difference of the images of b and a in a triangle holding the edge.
Complex edge_value(const SurfaceAdjacency& adjacency, const FaceMap& form, int a, int b);

}  // namespace qm
