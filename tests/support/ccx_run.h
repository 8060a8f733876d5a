// Running CalculiX (ccx) on a deck of ours with a material, a section and a
// static step appended, as a user does: for the tests that solve a deck.
#pragma once

#include <optional>
#include <string>

namespace qm::test {

bool ccx_installed();

struct TensionStep {
  double young = 200000, poisson = 0.3, thickness = 1.0;
  bool shell = false;           ///< *SHELL SECTION (and z held on every node) instead of *SOLID SECTION
  std::string element_set = "surface";
  std::string fixed_x, fixed_y;  ///< node sets held in x and in y
  std::string loaded;            ///< the surface pulled outwards
  double traction = 100;         ///< force per area on it
};

/// Appends the material, section and step to the deck at `inp` (a copy in its
/// folder, `name`.inp), runs ccx there and returns the total strain energy of the
/// element set, or nothing when ccx failed (its log is `name`.log).
std::optional<double> ccx_strain_energy(const std::string& inp, const std::string& name, const TensionStep& step);

}  // namespace qm::test
