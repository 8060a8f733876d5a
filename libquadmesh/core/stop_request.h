// A long computation run beside others asks between its steps whether its result is
// still wanted: a cone placement mapped beside one whose refusal ends the batch
// (pipeline/internal/cone_route.h cone_attempts_side_by_side) stops at its next
// solve rather than finishing a seamless map nobody reads.
#pragma once

#include "libquadmesh/core/error.h"

#include <functional>

namespace qm {

/// True when the computation's result is no longer wanted. Empty: never asked.
using StopRequest = std::function<bool()>;

/// Thrown by a computation that stopped on its StopRequest (an Error, so that
/// whoever catches a stage's failures catches it; the one who asked drops it).
class Stopped : public Error {
 public:
  Stopped() : Error(ErrorCode::unsupported, "stopped: its result is no longer wanted") {}
};

/// Throws Stopped when `stop` is set and returns true.
inline void stop_if_requested(const StopRequest& stop) {
  if (stop && stop()) throw Stopped();
}

}  // namespace qm
