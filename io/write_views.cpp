#include "io/write_views.h"

#include "io/atomic_file.h"
#include "io/gmsh_model.h"
#include "libquadmesh/core/error.h"

#include <fmt/format.h>
#include <gmsh.h>

namespace qm::io {

void write_views(const std::string& path, const OutputMesh& mesh,
                 const std::vector<FaceVectorView>& vectors,
                 const std::vector<CornerScalarView>& scalars) {
  check_output_path(path);
  if (format_of(path) != Format::msh)
    throw Error(ErrorCode::bad_input, fmt::format("{}: views are written as .msh only", path));
  write_atomically(path, [&](const std::string& temporary) {
    GmshSession session;
    const std::vector<std::size_t> tags = add_to_gmsh_model(mesh);
    write_gmsh_model(temporary, WriteOptions{}, session);
    gmsh::option::setNumber("PostProcessing.SaveMesh", 0);  // the mesh is written once, above
    auto add_view = [&](const std::string& name, const char* type,
                        const Eigen::MatrixX3d& values, int components) {
      const int view = gmsh::view::add(name);
      std::vector<std::vector<double>> data(tags.size());
      for (std::size_t i = 0; i < tags.size(); ++i) {
        const auto row = static_cast<Eigen::Index>(i);
        data[i] = {values(row, 0), values(row, 1), values(row, 2)};
      }
      gmsh::view::addModelData(view, 0, "quadmesh", type, tags, data, 0.0, components);
      gmsh::view::write(view, temporary, true);
    };
    for (const FaceVectorView& v : vectors) add_view(v.name, "ElementData", v.vectors, 3);
    for (const CornerScalarView& s : scalars) add_view(s.name, "ElementNodeData", s.values, 1);
    const std::string error = session.first_error();
    if (!error.empty())
      throw Error(ErrorCode::bad_input, fmt::format("{}: Gmsh could not write the views: {}", path, error));
  });
}

}  // namespace qm::io
