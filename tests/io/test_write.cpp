// Writing: a round trip through every output format keeps the counts, and a
// failed write leaves no file behind.
#include "io/read_surface.h"
#include "io/write_mesh.h"
#include "libquadmesh/core/error.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace qm;

namespace {

struct Counts {
  std::size_t points = 0, triangles = 0;
};

/// Abaqus .inp: lines of the *NODE block and of *ELEMENT blocks of type CPS3/S3.
Counts count_inp(const std::string& path) {
  std::ifstream in(path);
  Counts c;
  std::string line, block;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '*') {
      block = line.rfind("*NODE", 0) == 0 ? "node"
              : line.rfind("*ELEMENT", 0) == 0 && line.find("3") != std::string::npos ? "tri"
                                                                                      : "";
      if (line.find("T3D2") != std::string::npos) block = "";
      continue;
    }
    if (block == "node") ++c.points;
    if (block == "tri") ++c.triangles;
  }
  return c;
}

/// SU2: NPOIN and the elements of type 5 (triangle) in the volume section.
Counts count_su2(const std::string& path) {
  std::ifstream in(path);
  Counts c;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("NPOIN=", 0) == 0) c.points = std::stoul(line.substr(6));
    if (line.rfind("NELEM=", 0) == 0) {
      const std::size_t n = std::stoul(line.substr(6));
      for (std::size_t i = 0; i < n && std::getline(in, line); ++i)
        if (line.rfind("5 ", 0) == 0 || line.rfind("5\t", 0) == 0) ++c.triangles;
    }
  }
  return c;
}

io::OutputMesh annulus_with_groups(const TriangleSoup& soup, int sectors) {
  io::OutputMesh mesh = io::output_mesh_of(soup);
  io::LineGroup inner{"boundary_0", {}, {}}, outer{"boundary_1", {}, {}};
  const int last_ring = static_cast<int>(soup.points.size()) - sectors;
  for (int j = 0; j < sectors; ++j) {
    inner.edges.push_back({j, (j + 1) % sectors});
    outer.edges.push_back({last_ring + j, last_ring + (j + 1) % sectors});
  }
  mesh.line_groups = {inner, outer};
  return mesh;
}

}  // namespace

TEST_CASE("round trip of every output format keeps the counts") {
  const std::string dir = test::scratch_dir("write_roundtrip");
  const int sectors = 20;
  const TriangleSoup soup = test::annulus(1.0, 2.0, 4, sectors);
  const io::OutputMesh mesh = annulus_with_groups(soup, sectors);

  for (const char* ext : {"msh", "vtk", "bdf", "unv", "mesh", "obj", "off", "ply"}) {
    CAPTURE(ext);
    const std::string path = dir + "/annulus." + ext;
    io::write_mesh(path, mesh);
    const io::SurfaceFile back = io::read_surface(path);
    CHECK(back.soup.points.size() == soup.points.size());
    CHECK(back.soup.triangles.size() == soup.triangles.size());
    // no temporary file is left beside it
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      (void)entry;
      ++files;
    }
    CHECK(files == 1);
    std::filesystem::remove(path);
  }

  io::WriteOptions v22;
  v22.msh_version = 2.2;
  io::write_mesh(dir + "/annulus22.msh", mesh, v22);
  std::ifstream head(dir + "/annulus22.msh");
  std::string magic, version;
  head >> magic >> version;
  CHECK(version == "2.2");
  CHECK(io::read_surface(dir + "/annulus22.msh").soup.triangles.size() == soup.triangles.size());

  io::write_mesh(dir + "/annulus.inp", mesh);
  const Counts inp = count_inp(dir + "/annulus.inp");
  CHECK(inp.points == soup.points.size());
  CHECK(inp.triangles == soup.triangles.size());

  io::write_mesh(dir + "/annulus.su2", mesh);
  const Counts su2 = count_su2(dir + "/annulus.su2");
  CHECK(su2.points == soup.points.size());
  CHECK(su2.triangles == soup.triangles.size());
}

TEST_CASE("MSH output carries the line groups as named physical curves") {
  const std::string dir = test::scratch_dir("write_groups");
  const TriangleSoup soup = test::annulus(1.0, 2.0, 3, 12);
  io::write_mesh(dir + "/groups.msh", annulus_with_groups(soup, 12));
  std::ifstream in(dir + "/groups.msh");
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str().find("1 1 \"boundary_0\"") != std::string::npos);
  CHECK(text.str().find("1 2 \"boundary_1\"") != std::string::npos);
  CHECK(text.str().find("2 3 \"surface\"") != std::string::npos);
}

TEST_CASE("quads are written as quads") {
  const std::string dir = test::scratch_dir("write_quads");
  io::OutputMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  mesh.faces = {{0, 1, 2, 3}, {1, 4, 5, 2}};
  io::write_mesh(dir + "/quads.off", mesh);
  std::ifstream in(dir + "/quads.off");
  std::string magic;
  std::size_t v = 0, f = 0;
  in >> magic >> v >> f;
  CHECK(v == 6);
  CHECK(f == 2);
  const io::SurfaceFile back = io::read_surface(dir + "/quads.off");
  CHECK(back.polygons_split == 2);
  CHECK(back.soup.triangles.size() == 4);
}

TEST_CASE("bad destinations are refused before writing, and leave nothing") {
  const std::string dir = test::scratch_dir("write_bad");
  const io::OutputMesh mesh = io::output_mesh_of(test::grid(2));
  CHECK_THROWS_AS(io::write_mesh(dir + "/out.xyz", mesh), Error);
  CHECK_THROWS_AS(io::write_mesh(dir + "/missing/out.msh", mesh), Error);
  CHECK_THROWS_AS(io::check_output_path(dir + "/out.stl"), Error);  // STL is input-only
  CHECK(std::filesystem::is_empty(dir));
}
