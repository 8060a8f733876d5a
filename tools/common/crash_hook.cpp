#include "tools/common/crash_hook.h"

#include <cstdlib>
#include <sstream>

namespace qm::tools {

bool crash_requested(const char* variable, const std::string& name) {
  const char* value = std::getenv(variable);
  if (value == nullptr) return false;
  std::stringstream list(value);
  for (std::string item; std::getline(list, item, ',');)
    if (item == name) return true;
  return false;
}

}  // namespace qm::tools
