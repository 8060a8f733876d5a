// The input report of `quadmesh info`: as JSON and as text.
#pragma once

#include "tools/common/input_surface.h"

#include <nlohmann/json.hpp>

#include <string>

namespace qm::tools {

/// One JSON object: counts, topology, defects, and the method's verdict.
nlohmann::ordered_json topology_json(const InputSurface& in, const Applicability& verdict);

/// The same facts as aligned text lines for a terminal.
std::string topology_text(const InputSurface& in, const Applicability& verdict);

}  // namespace qm::tools
