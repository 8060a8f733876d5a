#include "io/gmsh_session.h"

#include "io/text_diagnostics.h"

#include <gmsh.h>

namespace qm::io {

namespace {
struct GmshRuntime {
  GmshRuntime() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 2);
    // The API's default (2: throw) leaves Gmsh unable to read any later file once
    // one read failed; readers check the log for errors instead.
    gmsh::option::setNumber("General.AbortOnError", 0);
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
  for (const std::string& line : log()) {
    if (line.rfind("Error", 0) != 0) continue;
    const auto text = line.find_first_not_of(" :", 5);  // drop Gmsh's "Error   : "
    return printable(text == std::string::npos ? line : line.substr(text), 200);
  }
  return {};
}

}  // namespace qm::io
