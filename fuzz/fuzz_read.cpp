// libFuzzer target: one reader on arbitrary bytes. The bytes are written to a file
// with the extension this target is built for (QM_FUZZ_EXTENSION: ".obj", ".off",
// ".ply", ".stl", ".msh"), read by io::read_surface (Gmsh's formats in its sandboxed
// child) and the topology checks, then, as `quality` does, by io::read_polygon_mesh. A qm::Error is the expected answer to bad bytes; anything else (a crash, a
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

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Gmsh reads in a child process (io/child_process.h); a child forked from this
  // multi-threaded fuzzer can deadlock on a lock another thread held, so it gets
  // half of libFuzzer's 10 s per input and is then killed, as the program would
  // kill it after --cad-timeout
  qm::io::default_cad_sandbox().timeout_seconds = 5;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratch_path();
  write_file(path, data, size);
  try {
    const qm::io::SurfaceFile file = qm::io::read_surface(path);
    const qm::AnalyzedSurface surface = qm::analyze_topology(file.soup);
    (void)qm::assess_applicability(surface);
  } catch (const qm::Error&) {
    return 0;
  }
  // as `quadmesh quality` does: the polygon reader (Gmsh in this process for
  // MSH and STL) only gets files read_surface has read in its sandbox
  try {
    (void)qm::io::read_polygon_mesh(path);
  } catch (const qm::Error&) {
  }
  return 0;
}
