#include "io/gmsh_session.h"

#include <gmsh.h>

namespace qm::io {

namespace {
struct GmshRuntime {
  GmshRuntime() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 2);
  }
  ~GmshRuntime() { gmsh::finalize(); }
};
}  // namespace

GmshSession::GmshSession() {
  static GmshRuntime runtime;
  gmsh::clear();
  gmsh::logger::start();
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
    gmsh::clear();
  } catch (...) {
  }
}

std::vector<std::string> GmshSession::log() const {
  std::vector<std::string> lines;
  gmsh::logger::get(lines);
  return lines;
}

std::string GmshSession::first_error() const {
  for (const std::string& line : log())
    if (line.rfind("Error", 0) == 0) return line;
  return {};
}

}  // namespace qm::io
