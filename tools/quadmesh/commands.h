// The subcommands of the quadmesh program. Each returns the process exit status
// and throws qm::Error for bad input (the caller prints it as one line).
#pragma once

#include <string>

namespace qm::tools {

struct CommonOptions {
  bool quiet = false;
  bool largest_component = false;
  double cad_mesh_size = 0.0;  ///< 0: automatic
};

struct InfoOptions {
  std::string input;
  bool json = false;
};

struct MeshOptions {
  std::string input;
  std::string output;
  double size = 0.0;         ///< target quad edge length; 0: 1/60 of the bounding-box diagonal
  double msh_version = 4.1;
};

struct FormsOptions {
  std::string input;
  bool json = false;
  std::string views;  ///< -o: Gmsh views file (.msh), empty for none
  bool remesh = false;       ///< isotropic remeshing first
  bool repair = false;       ///< flips/splits curing negative cotangent weights
  double remesh_size = 0.0;  ///< its target edge length; 0: 0.4 x the mean edge length
};

int run_info(const InfoOptions& info, const CommonOptions& common);
int run_mesh(const MeshOptions& mesh, const CommonOptions& common);
int run_forms(const FormsOptions& forms, const CommonOptions& common);

}  // namespace qm::tools
