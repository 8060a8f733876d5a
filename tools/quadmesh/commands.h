// The subcommands of the quadmesh program. Each returns the process exit status
// and throws qm::Error for bad input (the caller prints it as one line).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace qm::tools {

struct CommonOptions {
  bool quiet = false;
  bool largest_component = false;
  double cad_mesh_size = 0.0;  ///< 0: automatic
  double cad_timeout = 300.0;  ///< --cad-timeout: seconds Gmsh may take on one input
  double cad_memory = 0.0;     ///< --cad-memory: GiB Gmsh may use; 0: automatic
  bool allow_geo_commands = false;  ///< --allow-geo-commands
  std::size_t threads = 0;          ///< --threads: worker threads; 0: all cores
};

struct InfoOptions {
  std::string input;
  bool json = false;
};

struct MeshOptions {
  std::string input;
  std::string output;
  std::string report;        ///< --report: JSON quality report, empty for none
  double size = 0.0;         ///< target quad edge length; 0: 1/60 of the bounding-box diagonal
  double size_relative = 0.0;  ///< --size P%: P/100 of the bounding-box diagonal
  std::size_t quads = 0;     ///< target quad count (wins over size)
  std::size_t max_quads = 5000000;  ///< --max-quads: refuse a size or count implying more quads
  int form = -1;             ///< -1: auto; else the symmetric basis form (from 0)
  std::vector<double> coefficients;  ///< --coeffs
  bool rotate = false;
  std::string singularities = "auto";  ///< abel | auto (QuadMeshOptions::singularities)
  std::string cone_placement = "greedy";  ///< greedy | cross-field (QuadMeshOptions::cone_placement)
  bool no_smoothing = false;            ///< --no-smoothing
  bool no_coarsening = false;           ///< --no-coarsening
  double corner_angle_deg = 30.0;
  double tip_angle_deg = 315.0;
  double max_deviation = 0.0;           ///< --max-deviation D; 0: half the size; < 0: off
  double max_deviation_relative = 0.0;  ///< --max-deviation P%: P/100 of the diagonal
  double msh_version = 4.1;
  int order = 1;             ///< --order: 1 linear quads, 2 quadratic
  bool complete = false;     ///< --complete: 9-node quadratic quads
  std::string element_type;  ///< --element-type: solver decks (io/deck_element.h); empty: from the geometry
  /// --each-component: every part (CAD physical surface group or connected set
  /// of triangles) meshed on its own, one physical surface each
  bool each_component = false;
  /// --skip-unsupported: with --each-component, leave out the parts the method
  /// cannot take (listed with their reason) instead of failing
  bool skip_unsupported = false;
};

struct FormsOptions {
  std::string input;
  bool json = false;
  std::string views;  ///< -o: Gmsh views file (.msh), empty for none
  bool remesh = false;       ///< isotropic remeshing first
  bool repair = false;       ///< flips/splits curing negative cotangent weights
  double remesh_size = 0.0;  ///< its target edge length; 0: 0.4 x the mean edge length
  std::size_t max_triangles = 5000000;   ///< --max-triangles: refuse a --remesh-size implying more
};

struct QualityOptions {
  std::string input;
  std::string reference;  ///< --reference: triangulated surface for the Hausdorff distance, or empty
  double size = 0.0;           ///< --size H: the target quad size the sizes are set against; 0: none
  double size_relative = 0.0;  ///< --size P%: P/100 of the bounding-box diagonal (the reference's, else the mesh's)
  bool json = false;
};

struct CompareOptions {
  std::string input;
  std::string out_dir;         ///< --out: reports and meshes; empty: compare-<input stem>
  double size = 0.0;           ///< target quad edge length; 0: 1/60 of the bounding-box diagonal
  double size_relative = 0.0;  ///< --size P%: P/100 of the bounding-box diagonal
  double timeout = 120.0;      ///< --timeout: seconds each method may run
  std::string gmsh = "gmsh";   ///< --gmsh: the Gmsh program the baselines run
};

struct BatchOptions {
  std::string list;          ///< LIST: a CSV (file,size,options) or a folder of inputs
  std::string out_dir;       ///< --out: the rows' outputs, summary.json, summary.md
  int jobs = 1;              ///< --jobs: rows at once
  std::string size;          ///< --size: the rows' size where LIST gives none ("" : mesh's default)
  double timeout = 600.0;    ///< --timeout: seconds each row may run
  std::size_t row = 0;       ///< --row K: only row K (from 1); 0: all, then the summary
  std::string collect_dir;   ///< --collect DIR: the summary of the rows DIR holds
  bool prepare = false;      ///< --prepare: write DIR/list.json, print the row count, run nothing
};

struct RenderOptions {
  std::string input;
  std::string output;          ///< -o: the picture (.svg)
  std::string color = "sj";    ///< --color: sj, angle, size or none (face_coloring_named)
  std::vector<double> view;    ///< --view x,y,z towards the viewer; empty: the most area
  double size = 0.0;           ///< --size: reference length of --color size; 0: the mean edge length
  double size_relative = 0.0;  ///< --size P%: P/100 of the bounding-box diagonal
  double width = 640;          ///< --width: the drawing's width in pixels (the legend is beside it)
};

int run_info(const InfoOptions& info, const CommonOptions& common);
int run_mesh(const MeshOptions& mesh, const CommonOptions& common);
int run_forms(const FormsOptions& forms, const CommonOptions& common);
int run_quality(const QualityOptions& quality, const CommonOptions& common);
int run_compare(const CompareOptions& compare, const CommonOptions& common);
int run_batch(const BatchOptions& batch, const CommonOptions& common);
int run_render(const RenderOptions& render, const CommonOptions& common);

}  // namespace qm::tools
