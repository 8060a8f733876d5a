// The meshers `quadmesh compare` runs side by side: ours and Gmsh's quad meshing
// (README "quadmesh compare"). Each one is a command for a child process that
// writes one mesh file into the output folder.
#pragma once

#include <string>
#include <vector>

namespace qm::tools {

/// What every method is given: the same input and the same target size.
struct MethodSetup {
  std::string input;  ///< the user's file, absolute path
  bool cad = false;   ///< CAD input (.geo .step .brep .iges): Gmsh meshes it itself
  std::string
      triangulation;  ///< file name (in the output folder) of the input triangulation (.msh)
  double size = 0.0;  ///< target quad edge length (absolute)
  std::string self;   ///< this program's executable, for `quadmesh mesh`
  std::string gmsh = "gmsh";                 ///< the Gmsh command-line program
  std::string gmsh_version;                  ///< what `gmsh --version` printed ("" if nothing)
  std::vector<std::string> mesh_extra_args;  ///< passed on to `quadmesh mesh` (global options)
  /// Discrete inputs: the feature angle of Gmsh's ClassifySurfaces (degrees), as in
  /// Gmsh's tutorial t13.
  double feature_angle_deg = 40.0;
};

struct Method {
  std::string name;               ///< "quadmesh" or "gmsh-..." (report.json "name")
  std::string description;        ///< what it does, with the Gmsh options, for the report
  std::string mesh_file;          ///< the mesh it writes, a file name in the output folder
  std::string script_file;        ///< Gmsh: the .geo script it runs (in the output folder); else ""
  std::string script;             ///< the text of that script
  std::vector<std::string> argv;  ///< the command, run in the output folder
  std::string skipped_because;    ///< "" to run it; else why this Gmsh cannot (the report says it)
};

/// The quasi-structured mesher splits every quad of its first mesh in four, so it
/// is given twice the target size (Gmsh's reference build notes; measured on
/// plate-two-holes at 1.5%: mean edge 1.72 for a target of 1.75).
inline constexpr double kQuasiStructuredSizeFactor = 2.0;

/// Ours first, then the Gmsh baselines:
///  - quadmesh: `quadmesh mesh INPUT -o quadmesh.msh --size H -q`;
///  - gmsh-blossom-same-triangulation: the input triangulation merged, CreateTopology
///    (without boundary curves Gmsh's smoothing moves the boundary), RecombineMesh
///    (Blossom, Mesh.RecombinationAlgorithm 1): quads of the triangulation's size;
///  - gmsh-frontal-blossom: remeshed at size H (Mesh.MeshSizeMin = Max = H) with
///    Frontal-Delaunay (Mesh.Algorithm 6) and Blossom recombination
///    (Mesh.RecombineAll 1, Mesh.RecombinationAlgorithm 1);
///  - gmsh-frontal-blossom-full-quad: the same with Mesh.RecombinationAlgorithm 3
///    (Blossom full-quad: meshed at 2H, recombined, every quad split in four);
///  - gmsh-quad-frontal: Frontal-Delaunay for Quads (Mesh.Algorithm 8) + Blossom;
///  - gmsh-quasi-structured: Gmsh's quasi-structured quad mesher (Mesh.Algorithm 11,
///    with its own defaults for its size map and topology optimizations) at
///    kQuasiStructuredSizeFactor x H; skipped (skipped_because) unless
///    setup.gmsh_version is 4.9 or later (gmsh_version.h).
/// CAD inputs are merged directly; discrete ones through the triangulation,
/// ClassifySurfaces{feature angle, 1 (boundary), 1 (parametrizable patches), Pi}
/// and CreateGeometry. Every script ends with Mesh.SaveAll = 1 and a Save. Every
/// method is listed whatever the version, so that the files compare may write are
/// known before it runs.
std::vector<Method> comparison_methods(const MethodSetup& setup);

}  // namespace qm::tools
