// quadmesh mesh --each-component: an assembly's parts each meshed on its own into
// one output with a physical surface per part; parts the method cannot take are
// listed (and left out with --skip-unsupported, else the run fails).
#include "io/gmsh_session.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/topology/surface_parts.h"
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>
#include <gmsh.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>

using namespace qm;

namespace {

/// Per physical surface of a Gmsh mesh file: its name and its faces as a mesh.
std::map<std::string, PolygonMesh> physical_surfaces(const std::string& path) {
  io::GmshSession session;
  gmsh::open(path);
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::map<std::size_t, Vec3> node;
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    node[node_tags[i]] = Vec3(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]);
  std::map<std::string, PolygonMesh> out;
  std::vector<std::pair<int, int>> groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    PolygonMesh& mesh = out[name];
    std::map<std::size_t, int> index;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
      for (std::size_t k = 0; k < types.size(); ++k) {
        const std::size_t corners = types[k] == 3 ? 4 : 3;
        for (std::size_t e = 0; e < tags[k].size(); ++e) {
          std::vector<int> face;
          for (std::size_t c = 0; c < corners; ++c) {
            const std::size_t n = nodes[k][e * corners + c];
            if (!index.count(n)) {
              index[n] = static_cast<int>(mesh.points.size());
              mesh.points.push_back(node[n]);
            }
            face.push_back(index[n]);
          }
          mesh.faces.push_back(face);
        }
      }
    }
  }
  return out;
}

/// The names of the physical curves of a Gmsh mesh file.
std::vector<std::string> physical_curves(const std::string& path) {
  io::GmshSession session;
  gmsh::open(path);
  std::vector<std::pair<int, int>> groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  std::vector<std::string> names;
  for (const auto& [dim, tag] : groups) {
    names.emplace_back();
    gmsh::model::getPhysicalName(dim, tag, names.back());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST_CASE("surface_parts: physical surface groups, then connected sets; names from the groups") {
  // four triangles: two sharing an edge (group "a"), one touching them at a point
  // but in group "b", and one alone in no group
  TriangleSoup soup;
  soup.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0),
                 Vec3(2, 2, 0), Vec3(5, 5, 0), Vec3(6, 5, 0), Vec3(5, 6, 0)};
  soup.triangles = {{0, 1, 2}, {1, 3, 2}, {3, 4, 5}, {6, 7, 8}};
  soup.triangle_labels = {11, 12, 13, 14};
  soup.cad.surface_groups = {{1, "a", {11, 12}}, {2, "", {13}}};
  const std::vector<SurfacePart> parts = surface_parts(soup);
  REQUIRE(parts.size() == 3);
  CHECK(parts[0].name == "a");
  CHECK(parts[0].triangles == std::vector<int>{0, 1});
  CHECK(parts[1].name == "surface_group_2");
  CHECK(parts[1].triangles == std::vector<int>{2});
  CHECK(parts[2].name == "part_1");
  CHECK(parts[2].triangles == std::vector<int>{3});
  CHECK(part_soup(soup, parts[2]).points.size() == 3);

  soup.cad.surface_groups.clear();  // no groups: connected sets (sharing a point) alone
  const std::vector<SurfacePart> connected = surface_parts(soup);
  REQUIRE(connected.size() == 2);
  CHECK(connected[0].name == "part_1");
  CHECK(connected[0].triangles == std::vector<int>{0, 1, 2});
  CHECK(connected[1].name == "part_2");
}

TEST_CASE("the five-part assembly: four parts meshed, one physical surface each, the disk left out and listed") {
  const std::string dir = test::scratch_dir("assembly");
  const std::string out = dir + "/assembly.msh", report = dir + "/assembly.json";
  const std::string input = test::quoted(test::example("assembly-five-parts.geo"));

  // without --skip-unsupported: the disk fails the run, named with its reason, and nothing is written
  const test::Run refused = test::quadmesh("mesh " + input + " -o " + test::quoted(out) + " --size 2% --each-component -q");
  CHECK(refused.status == 4);
  REQUIRE(refused.error_lines().size() == 1);
  CHECK(refused.error_lines()[0].find("1 of 5 parts cannot be meshed: blank_disk (genus 0 with 1 boundary, chi = 1") !=
        std::string::npos);
  CHECK(refused.error_lines()[0].find("--skip-unsupported") != std::string::npos);
  CHECK(!std::filesystem::exists(out));

  const test::Run run = test::quadmesh("mesh " + input + " -o " + test::quoted(out) + " --report " +
                                       test::quoted(report) + " --size 2% --each-component --skip-unsupported -q");
  REQUIRE_MESSAGE(run.status == 0, run.err);
  // the summary: one row per part, the disk's with its reason
  CHECK(run.out.find("blank_disk               unsupported genus 0 with 1 boundary, chi = 1") != std::string::npos);
  CHECK(run.out.find("total: 4 of 5 parts meshed") != std::string::npos);

  // the file: one physical surface per meshed part, pure quads, each with its part's topology
  const std::map<std::string, std::pair<int, int>> expected = {  // chi, boundary loops
      {"plate_two_holes", {-1, 3}},
      {"washer", {0, 2}},
      {"bracket_three_holes", {-2, 4}},
      {"slotted_strip", {0, 2}}};
  const std::map<std::string, PolygonMesh> surfaces = physical_surfaces(out);
  REQUIRE(surfaces.size() == expected.size());
  for (const auto& [name, topology] : expected) {
    CAPTURE(name);
    REQUIRE(surfaces.count(name) == 1);
    const QuadQuality q = quad_quality(surfaces.at(name), nullptr);
    CHECK(q.quads > 20);
    CHECK(q.triangles == 0);
    CHECK(q.inverted == 0);
    CHECK(q.manifold);
    CHECK(q.euler_characteristic == topology.first);
    CHECK(q.boundary_loops == topology.second);
  }
  // the boundary groups: each part's loops, named after the part
  CHECK(physical_curves(out) ==
        std::vector<std::string>{"bracket_three_holes_boundary_0", "bracket_three_holes_boundary_1",
                                 "bracket_three_holes_boundary_2", "bracket_three_holes_boundary_3",
                                 "plate_two_holes_boundary_0",     "plate_two_holes_boundary_1",
                                 "plate_two_holes_boundary_2",     "slotted_strip_boundary_0",
                                 "slotted_strip_boundary_1",       "washer_boundary_0",
                                 "washer_boundary_1"});

  // the report: one entry per part, the totals, the same quads as the file
  const nlohmann::json j = nlohmann::json::parse(test::slurp(report));
  REQUIRE(j["parts"].size() == 5);
  CHECK(j["totals"]["parts"] == 5);
  CHECK(j["totals"]["meshed"] == 4);
  CHECK(j["totals"]["unsupported"] == 1);
  std::size_t quads = 0;
  for (const auto& part : j["parts"]) {
    if (part["name"] == "blank_disk") {
      CHECK(part["status"] == "unsupported");
      CHECK(part["input"]["euler_characteristic"] == 1);
      continue;
    }
    CHECK(part["status"] == "meshed");
    CHECK(part["quality"]["euler_characteristic"] == expected.at(part["name"].get<std::string>()).first);
    quads += part["quality"]["quads"].get<std::size_t>();
  }
  CHECK(j["quality"]["quads"] == quads);
  CHECK(j["totals"]["quads"] == quads);
}

TEST_CASE("--each-component refuses the options that speak of one surface") {
  const std::string input = test::quoted(test::example("assembly-five-parts.geo"));
  const std::string out = test::quoted(test::scratch_dir("assembly_options") + "/a.msh");
  CHECK(test::quadmesh("mesh " + input + " -o " + out + " --each-component --largest-component -q").status == 2);
  CHECK(test::quadmesh("mesh " + input + " -o " + out + " --each-component --quads 100 -q").status == 2);
  CHECK(test::quadmesh("mesh " + input + " -o " + out + " --skip-unsupported -q").status == 2);
}
