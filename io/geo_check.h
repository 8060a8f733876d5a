// Checking a Gmsh .geo script before Gmsh runs it (README "Limits").
//
// A .geo file is a program: it can run shell commands (SystemCall), write files
// (Printf > "f", Save, Print), create folders, end the process (Exit) and read any
// file on the machine (Include, Merge, ShapeFromFile). Reading an input must do
// none of that, so the script and every .geo it includes are scanned first (with
// comments and string contents told apart from code, as Gmsh's own lexer does)
// and such commands are refused.
#pragma once

#include <string>

namespace qm::io {

/// Throws qm::Error(bad_input) with one line "FILE: line N: COMMAND ...; refused
/// (CadSandbox::allow_geo_commands allows it)" for the first command of the script `path`
/// (or of a .geo it includes, checked the same way) that runs a program, writes,
/// creates or deletes a file, exits, or reads a file outside the script's folder
/// or through a computed path. Include cycles and includes nested deeper than 20
/// are refused even when `allow_commands` is true (Gmsh would recurse until it
/// runs out of file handles); everything else is then allowed.
void check_geo_script(const std::string& path, bool allow_commands);

}  // namespace qm::io
