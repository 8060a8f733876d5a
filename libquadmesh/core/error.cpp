#include "libquadmesh/core/error.h"

namespace qm {

void assertion_failed(const char* expr, const char* file, int line, const std::string& note) {
  std::string message = std::string(file) + ":" + std::to_string(line) + ": assertion failed: " + expr;
  if (!note.empty()) message += " (" + note + ")";
  throw AssertionError(message);
}

}  // namespace qm
