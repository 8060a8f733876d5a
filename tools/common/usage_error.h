// A usage error: a bad command line or output path (exit 2, README "Exit codes").
#pragma once

#include <stdexcept>
#include <string>

namespace qm::tools {

/// Thrown by the tools for exit status 2; what() is the whole message, printed
/// after "quadmesh: error: ".
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace qm::tools
