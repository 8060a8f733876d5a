// Access to the Gmsh SDK, which is one global state per process.
//
// GmshSession initializes Gmsh once (silenced: nothing reaches the terminal),
// starts from an empty model, and collects Gmsh's log so that readers can turn
// Gmsh errors into qm::Error messages.
#pragma once

#include <string>
#include <vector>

namespace qm::io {

class GmshSession {
 public:
  GmshSession();   ///< initializes Gmsh if needed, clears the model, starts the log
  ~GmshSession();  ///< clears the model and stops the log (Gmsh stays initialized)
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// The first "Error" line Gmsh logged since the session started, or "".
  std::string first_error() const;
  /// Every log line since the session started.
  std::vector<std::string> log() const;
};

}  // namespace qm::io
