// The library names options by their struct fields ("QuadMeshOptions::form",
// qm::Error::option()); the command line says them by its flags, and counts the
// symmetric forms from 1. Every library message the tool prints (errors, the
// applicability verdict) goes through command_line_wording.
#pragma once

#include <string>

namespace qm::tools {

/// `message` with every option the library names said as the command line's flag
/// ("QuadMeshOptions::coefficients" -> "--coeffs", "largest_component()" ->
/// "--largest-component"), and a form index "QuadMeshOptions::form = K" as
/// "--form K+1" (with its range "(0 to G-1)" as "(1 to G)").
std::string command_line_wording(const std::string& message);

}  // namespace qm::tools
