// `quadmesh compare` runs each mesher in a child process with a time limit. The
// machinery lives in io/child_process.h (readers use it for Gmsh too); these
// names keep compare's code as it was.
#pragma once

#include "io/child_process.h"

namespace qm::tools {

using io::ChildOptions;
using io::ChildResult;
using io::ChildStatus;
using io::own_executable;
using io::run_child;
using io::status_name;

}  // namespace qm::tools
