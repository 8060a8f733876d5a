// Exit statuses shared by every quadmesh program (README "Exit codes").
#pragma once

#include "libquadmesh/core/error.h"

namespace qm::tools {

enum ExitCode : int {
  exit_ok = 0,
  exit_internal = 1,     ///< a bug or a numerical failure
  exit_usage = 2,        ///< bad command line or output path
  exit_bad_input = 3,    ///< unreadable file or not a valid surface
  exit_unsupported = 4,  ///< valid surface the method does not apply to, or not implemented
};

inline int exit_code_for(ErrorCode code) {
  switch (code) {
    case ErrorCode::bad_input: return exit_bad_input;
    case ErrorCode::unsupported: return exit_unsupported;
    case ErrorCode::solver: return exit_internal;
  }
  return exit_internal;
}

}  // namespace qm::tools
