#include "tests/support/ccx_run.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace qm::test {

bool ccx_installed() { return std::system("command -v ccx > /dev/null 2>&1") == 0; }

std::optional<double> ccx_strain_energy(const std::string& inp, const std::string& name, const TensionStep& s) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(inp).parent_path();
  {
    std::ifstream in(inp);
    std::ofstream out(dir / (name + ".inp"));
    out << in.rdbuf();
    out << "*MATERIAL, NAME=TESTMAT\n*ELASTIC\n" << s.young << ", " << s.poisson << "\n";
    out << (s.shell ? "*SHELL SECTION" : "*SOLID SECTION") << ", ELSET=" << s.element_set
        << ", MATERIAL=TESTMAT\n" << s.thickness << "\n";
    out << "*STEP\n*STATIC\n*BOUNDARY\n" << s.fixed_x << ", 1\n" << s.fixed_y << ", 2\n";
    if (s.shell) out << "NALL, 3\n";
    out << "*DSLOAD\n" << s.loaded << ", P, " << -s.traction << "\n";
    out << "*EL PRINT, ELSET=" << s.element_set << ", TOTALS=ONLY\nELSE\n*END STEP\n";
  }
  const std::string command =
      "cd '" + dir.string() + "' && ccx " + name + " > " + name + ".log 2>&1";
  if (std::system(command.c_str()) != 0) return std::nullopt;
  std::ifstream dat(dir / (name + ".dat"));
  std::string line;
  while (std::getline(dat, line))
    if (line.find("total internal energy") != std::string::npos) {
      double energy = 0;
      if (dat >> energy) return energy;
    }
  return std::nullopt;
}

}  // namespace qm::test
