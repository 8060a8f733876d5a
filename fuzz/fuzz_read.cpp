// libFuzzer target: one reader on arbitrary bytes. The bytes are written to a file
// with the extension this target is built for (QM_FUZZ_EXTENSION: ".obj", ".off",
// ".ply", ".stl", ".msh"), read by io::read_surface and io::read_polygon_mesh (the
// readers of `mesh` and of `quality`), and what is read goes through the topology
// checks. A qm::Error is the expected answer to bad bytes; anything else (a crash, a
// sanitizer report, another exception, a hang or an allocation libFuzzer's limits
// catch) is a finding.
#include "io/read_polygon_mesh.h"
#include "io/read_surface.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/topology/applicability.h"
#include "libquadmesh/topology/topology_report.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace {

/// A file of this process's own, rewritten for every input.
const std::string& scratch_path() {
  static const std::string path =
      "/tmp/quadmesh-fuzz-" + std::to_string(::getpid()) + QM_FUZZ_EXTENSION;
  return path;
}

void write_file(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return;
  if (size > 0) std::fwrite(data, 1, size, f);
  std::fclose(f);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratch_path();
  write_file(path, data, size);
  try {
    const qm::io::SurfaceFile file = qm::io::read_surface(path);
    const qm::AnalyzedSurface surface = qm::analyze_topology(file.soup);
    (void)qm::assess_applicability(surface);
  } catch (const qm::Error&) {
  }
  try {
    (void)qm::io::read_polygon_mesh(path);
  } catch (const qm::Error&) {
  }
  return 0;
}
