// Test inputs: generated surfaces with known topology, and the shared meshes of
// ../shared/data with the numbers of MANIFEST.md.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <array>
#include <string>
#include <vector>

namespace qm::test {

/// Path of a shared mesh (../shared/data/NAME) or of an example (examples/NAME).
std::string shared_mesh(const std::string& name);
std::string example(const std::string& name);
/// A fresh empty folder under the system temp dir for one test (its name has the
/// process id, so that test runs at the same time keep apart), removed with its
/// files when the test program exits (kept with QUADMESH_KEEP_TEST_FILES set).
std::string scratch_dir(const std::string& test_name);
/// Writes `text` to dir/name (a .geo written by a test); returns the path.
std::string write_text(const std::string& dir, const std::string& name, const std::string& text);
/// A generated plate's .geo text (OpenCASCADE, as scripts/plate-sweep writes
/// them): a `width` x `height` rectangle, its corners rounded with radius `fillet`
/// (0: sharp), minus the round holes {x, y, radius}.
std::string plate_geo(double width, double height, double fillet, const std::vector<std::array<double, 3>>& holes);
/// A 150 x 50 CAD plate with five round holes, two of them 6.6 apart (OpenCASCADE
/// .geo text): its first rounding at 1.5% leaves folds and dropped cells.
std::string five_hole_plate_geo();
/// A 150 x 50 CAD plate with six round holes, one 4.15 from the plate's edge with
/// two boundary zeros on its far side (p7 of scripts/plate-sweep): at 1.5% they
/// were merged and the quads left a gap beside the hole; at 1.2% the quads'
/// boundary still leaves the hole's.
std::string edge_hole_plate_geo();
/// A 120 x 50 CAD plate with seven holes side by side (p13 of scripts/plate-sweep):
/// squares turned to each other's holes fold the map between them.
std::string crowded_holes_plate_geo();
/// A 200 x 40 CAD L-bracket with an arm 100 long and 20 wide and three holes
/// (OpenCASCADE .geo text): every symmetric form decays along the arm, and the
/// quads cannot conform (README Limits).
std::string long_arm_bracket_geo();

/// Planar annulus r0 <= |z| <= r1 with `rings` x `sectors` quads split in two
/// (genus 0, 2 boundaries, chi 0).
TriangleSoup annulus(double r0, double r1, int rings, int sectors);
/// Planar unit disk: a fan-refined polar grid (genus 0, 1 boundary, chi 1).
TriangleSoup disk(int rings, int sectors);
/// A planar sector of angle `theta` and radius `radius` round the origin (the tip,
/// vertex 0): `rings` x `sectors` polar cells split in two, a fan of triangles at
/// the origin. Vertex 1 + (i - 1)(sectors + 1) + j is ring i (at radius x i /
/// rings), ray j (at angle theta j / sectors).
TriangleSoup sector(double theta, int rings, int sectors, double radius = 1.0);
/// Octahedron-based sphere (closed, genus 0, chi 2).
TriangleSoup sphere();
/// Torus of revolution (closed, genus 1, chi 0).
TriangleSoup torus(double R, double r, int u, int v);
/// Möbius strip (non-orientable, 1 boundary loop, chi 0).
TriangleSoup moebius(int segments);
/// Two disjoint disks.
TriangleSoup two_components();
/// Two triangles sharing one vertex only (non-manifold vertex).
TriangleSoup bow_tie();
/// Three triangles on one edge (non-manifold edge).
TriangleSoup book();
/// A square grid in the plane, n x n cells, each split in two (a disk).
TriangleSoup grid(int n);
/// The L-shape [0, 2] x [0, 2] minus (1, 2] x (1, 2], on a grid of n x n cells per
/// unit square, each split in two (a disk with five convex corners and one concave).
TriangleSoup l_shape(int n);

/// `soup` without the triangles within `rings` rings of each vertex of `centres`
/// (each ring: the triangles at the vertices the last one reached), its unused
/// points dropped: a blocky hole cut out of a scan, as the shared ones were.
TriangleSoup cut_holes(const TriangleSoup& soup, const std::vector<int>& centres, int rings);

/// Writes a soup as OBJ (for command-line tests).
void write_obj(const TriangleSoup& soup, const std::string& path);

/// Expected topology of a shared mesh (MANIFEST.md).
struct ManifestEntry {
  std::string file;
  std::size_t vertices, faces;
  int boundary_loops, genus, euler_characteristic;
  bool manifold;
};
const std::vector<ManifestEntry>& manifest();

}  // namespace qm::test
