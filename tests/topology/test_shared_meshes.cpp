// The exact topology of every shared mesh, as MANIFEST.md states it.
#include "io/read_surface.h"
#include "libquadmesh/topology/applicability.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

using namespace qm;

TEST_CASE("shared meshes: MANIFEST topology") {
  for (const test::ManifestEntry& m : test::manifest()) {
    CAPTURE(m.file);
    const io::SurfaceFile file = io::read_surface(test::shared_mesh(m.file));
    const AnalyzedSurface s = analyze_topology(file.soup);
    const TopologyReport& r = s.report;
    CHECK(r.vertices == m.vertices);
    CHECK(r.faces == m.faces);
    CHECK(r.boundary_loop_count() == m.boundary_loops);
    CHECK(r.genus == m.genus);
    CHECK(r.euler_characteristic == m.euler_characteristic);
    CHECK(r.manifold() == m.manifold);
    CHECK(r.components.count == 1);
    CHECK(r.orientation.orientable);
    const Applicability a = assess_applicability(s);
    CHECK(a.supported == m.manifold);  // every valid shared mesh has chi <= 0
    if (a.supported) {
      CHECK(a.doubled_genus == (m.boundary_loops ? 2 * m.genus + m.boundary_loops - 1 : m.genus));
    } else {
      CHECK(a.code == ErrorCode::bad_input);
    }
  }
}

TEST_CASE("bunny-open.obj: the 1113 unreferenced scan vertices are dropped and counted") {
  const io::SurfaceFile file = io::read_surface(test::shared_mesh("bunny-open.obj"));
  const AnalyzedSurface s = analyze_topology(file.soup);
  CHECK(s.report.unreferenced_points == 1113);
  CHECK(s.report.points_read == 34834 + 1113);
}

TEST_CASE("ogre-body-pinched.obj: refused at a named pinched vertex") {
  const io::SurfaceFile file = io::read_surface(test::shared_mesh("ogre-body-pinched.obj"));
  const AnalyzedSurface s = analyze_topology(file.soup);
  CHECK(s.report.nonmanifold_vertices.size() == 3);
  CHECK(s.report.boundary.loops.size() == 9);  // two loops touch at the pinched vertices
  const Applicability a = assess_applicability(s);
  CHECK(a.code == ErrorCode::bad_input);
  CHECK(a.reason.rfind("non-manifold vertex ", 0) == 0);
  CHECK(a.reason.find("(3 such vertices)") != std::string::npos);
}
