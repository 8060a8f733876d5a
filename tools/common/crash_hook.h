// The test hook of the commands that run children (compare, batch): an
// environment variable names the children that raise SIGSEGV instead of running
// (io::ChildOptions::crash_on_purpose), as a crashing mesher would.
#pragma once

#include <string>

namespace qm::tools {

/// True when `name` is one of the comma-separated names in the environment
/// variable `variable` (QUADMESH_COMPARE_CRASH, QUADMESH_BATCH_CRASH).
bool crash_requested(const char* variable, const std::string& name);

}  // namespace qm::tools
