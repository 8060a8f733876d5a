#include "libquadmesh/quality/quad_distance.h"

#include "libquadmesh/quality/quad_quality.h"

namespace qm {

namespace {

/// S's samples for the distance to the quads (quad_distance).
std::vector<Vec3> reference_samples(const TriangleSoup& reference, const std::vector<Vec3>& quad_points,
                                    const std::vector<Triangle>& quad_triangles) {
  if (mean_edge_length(reference) > 0.25 * mean_edge_length(TriangleSoup{quad_points, quad_triangles, {}, {}, {}}))
    return surface_samples(reference.points, reference.triangles);
  std::vector<char> used(reference.points.size(), 0);
  for (const Triangle& t : reference.triangles)
    for (int v : t) used[static_cast<std::size_t>(v)] = 1;
  std::vector<Vec3> samples;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) samples.push_back(reference.points[i]);
  return samples;
}

}  // namespace

QuadDistance quad_distance(const PolygonMesh& mesh, const TriangleSoup& surface) {
  std::vector<Triangle> split;  // fans from corner 0: quads along the diagonal 0-2
  for (const std::vector<int>& face : mesh.faces)
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      split.push_back({face[0], face[i], face[i + 1]});
  std::vector<Vec3> samples = surface_samples(mesh.points, split);
  for (const std::vector<int>& face : mesh.faces) {
    if (face.size() == 3) continue;  // the triangle's centroid is already a sample
    Vec3 centroid = Vec3::Zero();
    for (int v : face) centroid += mesh.points[static_cast<std::size_t>(v)];
    samples.push_back(centroid / static_cast<double>(face.size()));
  }
  const FarthestSample forward = farthest_sample(samples, surface.points, surface.triangles);
  const FarthestSample backward = farthest_sample(reference_samples(surface, mesh.points, split), mesh.points, split);
  QuadDistance out;
  out.distance.forward = forward.distance;
  out.distance.backward = backward.distance;
  out.farthest = forward.distance >= backward.distance ? forward.point : backward.point;
  return out;
}

}  // namespace qm
