// The JSON form of a QuadQuality, shared by `quadmesh quality` and the report of
// `quadmesh mesh --report`.
#pragma once

#include "libquadmesh/quality/quad_quality.h"

#include <nlohmann/json.hpp>

namespace qm::tools {

/// One object with the fields of QuadQuality under their own (snake_case) names;
/// valence histograms as objects {"valence": count}; NaN and infinities as null.
nlohmann::ordered_json quality_json(const QuadQuality& q);

}  // namespace qm::tools
