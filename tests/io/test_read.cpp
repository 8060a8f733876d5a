// Reading: every input route, and every kind of bad file with its message.
#include "io/read_surface.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/topology/applicability.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <fstream>
#include <random>

using namespace qm;

namespace {

std::string write_text(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// The message read_surface throws for `path` (fails the test if it does not throw).
std::string read_error(const std::string& path) {
  try {
    io::read_surface(path);
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::bad_input);
    return e.what();
  }
  FAIL("no error for " << path);
  return {};
}

std::string file_head(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string s(bytes, '\0');
  in.read(&s[0], static_cast<std::streamsize>(bytes));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

}  // namespace

TEST_CASE("OBJ keeps the file's 1-based vertex numbers as labels") {
  const std::string dir = test::scratch_dir("read_obj");
  const std::string path =
      write_text(dir, "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const io::SurfaceFile f = io::read_surface(path);
  CHECK(f.soup.points.size() == 4);
  CHECK(f.soup.triangles.size() == 2);  // the quad is split
  CHECK(f.polygons_split == 1);
  CHECK(f.soup.point_label(0) == 1);
  CHECK(f.soup.point_label(3) == 4);
}

TEST_CASE("bad files: missing, empty, unknown, truncated, random bytes, NaN") {
  const std::string dir = test::scratch_dir("read_bad");
  CHECK(read_error(dir + "/nothing.obj").find("no such file") != std::string::npos);
  CHECK(read_error(write_text(dir, "empty.obj", "")).find("empty file") != std::string::npos);
  CHECK(read_error(write_text(dir, "mesh.xyz", "1 2 3")).find("unknown input format") !=
        std::string::npos);

  const std::string nan_obj =
      write_text(dir, "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
  const std::string nan_message = read_error(nan_obj);
  CHECK(nan_message.find("nan.obj: line 3:") != std::string::npos);
  CHECK(nan_message.find("not a finite number") != std::string::npos);

  const std::string bad_index = write_text(dir, "index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  CHECK(read_error(bad_index).find("index.obj: line 4: face refers to vertex 7") != std::string::npos);

  const std::string off = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  CHECK(io::read_surface(write_text(dir, "ok.off", off)).soup.triangles.size() == 2);
  const std::string truncated_off = write_text(dir, "truncated.off", off.substr(0, off.size() - 8));
  CHECK(read_error(truncated_off).find("ends after 1 of 2 faces") != std::string::npos);
  CHECK(read_error(write_text(dir, "inf.off", "OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n"))
            .find("inf.off: line 4: coordinate 'inf' is not a finite number") != std::string::npos);

  std::mt19937 random(42);
  std::string noise(4000, '\0');
  for (char& c : noise) c = static_cast<char>(random() & 0xff);
  for (const char* name : {"noise.obj", "noise.off", "noise.ply", "noise.stl", "noise.msh"}) {
    CAPTURE(name);
    const std::string message = read_error(write_text(dir, name, noise));
    CHECK(message.find(name) != std::string::npos);
  }

  std::string hinge = file_head(test::shared_mesh("hinge.stl"), 3000);
  hinge.resize(hinge.rfind('\n') + 1);  // cut between lines
  CHECK(read_error(write_text(dir, "cut.stl", hinge)).find("without 'endsolid'") !=
        std::string::npos);
}

TEST_CASE("truncated binary STL and MSH name what is missing") {
  const std::string dir = test::scratch_dir("read_truncated");
  // binary STL with 2 triangles announced and 1 present
  std::string stl(80, ' ');
  const unsigned char count[4] = {2, 0, 0, 0};
  stl.append(reinterpret_cast<const char*>(count), 4);
  stl.append(50, '\0');
  CHECK(read_error(write_text(dir, "short.stl", stl)).find("announces 2 triangles") !=
        std::string::npos);

  const std::string msh =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n";
  CHECK(read_error(write_text(dir, "cut.msh", msh)).find("section '$Nodes' opened at line 4 is not closed") !=
        std::string::npos);
}

TEST_CASE("STL through Gmsh merges coincident vertices (hinge.stl: 598)") {
  const io::SurfaceFile f = io::read_surface(test::shared_mesh("hinge.stl"));
  CHECK(f.soup.triangles.size() == 1212);
  const AnalyzedSurface s = analyze_topology(f.soup);
  CHECK(s.report.vertices == 598);
  CHECK(s.report.genus == 5);
}

TEST_CASE("CAD input: Gmsh triangulates it and the boundary keeps its curves and groups") {
  io::ReadOptions options;
  options.cad_mesh_size = 2.0;
  const io::SurfaceFile f = io::read_surface(test::example("plate-two-holes.geo"), options);
  CHECK(f.format == io::Format::geo);
  CHECK(f.cad_mesh_size == 2.0);
  const AnalyzedSurface s = analyze_topology(f.soup);
  CHECK(s.report.boundary_loop_count() == 3);
  CHECK(s.report.genus == 0);
  CHECK(s.report.euler_characteristic == -1);
  CHECK(assess_applicability(s).supported);

  // every boundary edge lies on a CAD curve
  std::size_t boundary_edges = 0;
  for (const auto& loop : s.report.boundary.loops) boundary_edges += loop.size();
  CHECK(f.soup.cad.edges.size() == boundary_edges);
  REQUIRE(f.soup.cad.groups.size() == 3);
  std::vector<std::string> names;
  for (const auto& g : f.soup.cad.groups) names.push_back(g.name);
  CHECK(names == std::vector<std::string>{"hole_left", "hole_right", "outer"});
  CHECK(f.soup.cad.groups[2].curves.size() == 4);  // the rectangle's four sides

  // a finer size gives more triangles
  options.cad_mesh_size = 1.0;
  const io::SurfaceFile finer = io::read_surface(test::example("plate-two-holes.geo"), options);
  CHECK(finer.soup.triangles.size() > 3 * f.soup.triangles.size());
}
