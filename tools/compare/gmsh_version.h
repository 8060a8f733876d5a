// Which Gmsh program compare runs: its version, as `gmsh --version` prints it,
// and what that version can do.
#pragma once

#include <optional>
#include <string>

namespace qm::tools {

struct GmshVersion {
  int major = 0, minor = 0, patch = 0;
};

/// The version at the start of `gmsh --version`'s line ("4.8.4", "4.15.2-git":
/// MAJOR.MINOR[.PATCH], anything after it ignored); nothing for any other text.
std::optional<GmshVersion> parse_gmsh_version(const std::string& text);

/// Whether `a` is `b` or later.
bool at_least(const GmshVersion& a, const GmshVersion& b);

/// The first Gmsh with the quasi-structured quad mesher, Mesh.Algorithm = 11
/// (Reberol, Georgiadis, Remacle 2021; Gmsh 4.9.0 release notes).
inline constexpr GmshVersion kQuasiStructuredSince{4, 9, 0};

/// "" when the Gmsh that printed `version_text` has the quasi-structured mesher;
/// else why it cannot run, in a few words for the report ("Gmsh 4.8.4 lacks it:
/// Mesh.Algorithm = 11 came with Gmsh 4.9; give a newer Gmsh with --gmsh").
std::string quasi_structured_missing(const std::string& version_text);

}  // namespace qm::tools
