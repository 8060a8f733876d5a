#include "tools/compare/methods.h"

#include "tools/compare/gmsh_version.h"

#include <fmt/format.h>

namespace qm::tools {

namespace {

/// The Gmsh options every remeshing baseline shares.
struct GmshRemesh {
  int algorithm = 6;      ///< Mesh.Algorithm: 6 Frontal-Delaunay, 8 Frontal-Delaunay for Quads
  int recombination = 1;  ///< Mesh.RecombinationAlgorithm: 1 Blossom, 3 Blossom full-quad
};

std::string script_header(const std::string& name) {
  return fmt::format(
      "// {}: a baseline of `quadmesh compare`, written by it.\n"
      "// Run it again with: gmsh {}.geo -\n",
      name, name);
}

/// The model to remesh: the CAD file itself, or the triangulation turned into a
/// parametrizable geometry as Gmsh's tutorial t13 does it (surfaces split at the
/// feature angle, boundary curves included, patches forced parametrizable, curves
/// not split: curve angle 180 degrees).
std::string load_model(const MethodSetup& setup) {
  if (setup.cad) return fmt::format("Merge \"{}\";\n", setup.input);
  return fmt::format(
      "Merge \"{}\";\n"
      "ClassifySurfaces{{{:g} * Pi / 180, 1, 1, Pi}};\n"
      "CreateGeometry;\n",
      setup.triangulation, setup.feature_angle_deg);
}

/// Gmsh's quasi-structured quad mesher with the defaults its authors chose (size
/// map from the background mesh, every topology optimization), at twice the size.
std::string quasi_structured_script(const MethodSetup& setup, const std::string& name) {
  const double size = kQuasiStructuredSizeFactor * setup.size;
  return script_header(name) + load_model(setup) +
         fmt::format(
             "Mesh.Algorithm = 11;  // quasi-structured quad (Gmsh >= 4.9)\n"
             "Mesh.MeshSizeMin = {:.17g};  // {:g} x the target: it splits its quads in four\n"
             "Mesh.MeshSizeMax = {:.17g};\n"
             "Mesh.SaveAll = 1;\n"
             "Mesh 2;\n"
             "Save \"{}.msh\";\n",
             size, kQuasiStructuredSizeFactor, size, name);
}

std::string remesh_script(const MethodSetup& setup, const std::string& name,
                          const GmshRemesh& options) {
  return script_header(name) + load_model(setup) +
         fmt::format(
             "Mesh.Algorithm = {};\n"
             "Mesh.RecombineAll = 1;\n"
             "Mesh.RecombinationAlgorithm = {};\n"
             "Mesh.MeshSizeMin = {:.17g};\n"
             "Mesh.MeshSizeMax = {:.17g};\n"
             "Mesh.SaveAll = 1;\n"
             "Mesh 2;\n"
             "Save \"{}.msh\";\n",
             options.algorithm, options.recombination, setup.size, setup.size, name);
}

Method gmsh_method(const MethodSetup& setup, std::string name, std::string description,
                   std::string script) {
  Method m;
  m.name = std::move(name);
  m.description = std::move(description);
  m.mesh_file = m.name + ".msh";
  m.script_file = m.name + ".geo";
  m.script = std::move(script);
  m.argv = {setup.gmsh, m.script_file, "-", "-nopopup"};
  return m;
}

}  // namespace

std::vector<Method> comparison_methods(const MethodSetup& setup) {
  std::vector<Method> methods;

  Method ours;
  ours.name = "quadmesh";
  ours.description = fmt::format(
      "this program: `quadmesh mesh` at --size {:.6g} (symmetric holomorphic differentials, quarter-turn cones "
      "where their quads miss the size band or a corner's quad count, quantized seamless parameterization)",
      setup.size);
  ours.mesh_file = "quadmesh.msh";
  ours.argv = {setup.self,
               "mesh",
               setup.input,
               "-o",
               ours.mesh_file,
               "--size",
               fmt::format("{:.17g}", setup.size),
               "-q"};
  ours.argv.insert(ours.argv.end(), setup.mesh_extra_args.begin(), setup.mesh_extra_args.end());
  methods.push_back(std::move(ours));

  const std::string same = "gmsh-blossom-same-triangulation";
  methods.push_back(gmsh_method(
      setup, same,
      "Gmsh's Blossom recombination (CreateTopology, RecombineMesh, Mesh.RecombinationAlgorithm "
      "= 1) of the input triangulation itself: its quads have the triangulation's size, not "
      "--size, and its points are the reference's (a Hausdorff distance of 0 by construction)",
      script_header(same) +
          fmt::format("Merge \"{}\";\n"
                      "CreateTopology;  // boundary curves, so that the boundary stays put\n"
                      "Mesh.RecombinationAlgorithm = 1;\n"
                      "Mesh.SaveAll = 1;\n"
                      "RecombineMesh;\n"
                      "Save \"{}.msh\";\n",
                      setup.triangulation, same)));

  const std::string source =
      setup.cad ? std::string("the CAD model meshed directly")
                : fmt::format(
                      "the triangulation through ClassifySurfaces (feature angle {:g} "
                      "deg) + CreateGeometry",
                      setup.feature_angle_deg);
  const std::string sizes = "Mesh.MeshSizeMin = Mesh.MeshSizeMax = --size";
  const std::string frontal = "gmsh-frontal-blossom";
  methods.push_back(gmsh_method(
      setup, frontal,
      fmt::format("Gmsh remeshing of {}: Frontal-Delaunay (Mesh.Algorithm = 6), Blossom "
                  "recombination (Mesh.RecombineAll = 1, Mesh.RecombinationAlgorithm = 1), {}",
                  source, sizes),
      remesh_script(setup, frontal, {6, 1})));

  const std::string full = "gmsh-frontal-blossom-full-quad";
  methods.push_back(gmsh_method(
      setup, full,
      fmt::format("as gmsh-frontal-blossom with Blossom full-quad (Mesh.RecombinationAlgorithm "
                  "= 3: meshed at twice the size, recombined, every element split in four), {}",
                  sizes),
      remesh_script(setup, full, {6, 3})));

  const std::string quad_frontal = "gmsh-quad-frontal";
  methods.push_back(gmsh_method(
      setup, quad_frontal,
      fmt::format("Gmsh remeshing of {}: Frontal-Delaunay for Quads (Mesh.Algorithm = 8) with "
                  "Blossom recombination (Mesh.RecombineAll = 1, Mesh.RecombinationAlgorithm = "
                  "1), {}",
                  source, sizes),
      remesh_script(setup, quad_frontal, {8, 1})));

  const std::string quasi = "gmsh-quasi-structured";
  Method qqs = gmsh_method(
      setup, quasi,
      fmt::format("Gmsh remeshing of {}: the quasi-structured quad mesher (Mesh.Algorithm = 11, Gmsh 4.9 and "
                  "later; its own defaults: size map from the background mesh, cavity and disk remeshing and "
                  "patterns on simple faces), Mesh.MeshSizeMin = Mesh.MeshSizeMax = {:g} x --size, since it "
                  "splits every quad of its first mesh in four",
                  source, kQuasiStructuredSizeFactor),
      quasi_structured_script(setup, quasi));
  qqs.skipped_because = quasi_structured_missing(setup.gmsh_version);
  methods.push_back(std::move(qqs));
  return methods;
}

}  // namespace qm::tools
