// Failures of the core library.
//
// Two kinds (docs/style.md, item 6):
//  - programmer errors (a broken precondition) go through QM_ASSERT, which throws
//    AssertionError with the file and line;
//  - data-dependent failures (bad input, a surface the method does not apply to,
//    a solver that did not converge) throw qm::Error with a typed code and a
//    message that names the offending element.
// The library never prints and never exits; tools map codes to exit statuses.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace qm {

enum class ErrorCode {
  bad_input,    ///< the input is malformed or not a valid surface (exit status 3)
  unsupported,  ///< a valid surface the method does not apply to (exit status 4)
  solver,       ///< a numerical stage failed (exit status 1)
};

/// A data-dependent failure. what() is one line that names the problem and where.
/// A failure caused by the value of an option names the option in what() by its
/// struct field ("QuadMeshOptions::form"; a function such as
/// "largest_component()" when that is the remedy), and `option()` returns that
/// same name, so that a tool can say it its own way (a command-line flag). Indices
/// in such messages count from 0, as the field does.
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message, std::string option = {})
      : std::runtime_error(message), code_(code), option_(std::move(option)) {}
  ErrorCode code() const { return code_; }
  /// The option what() names, spelled as in what(); empty when none.
  const std::string& option() const { return option_; }

 private:
  ErrorCode code_;
  std::string option_;
};

/// A broken precondition: a bug in the caller, never a property of the input.
class AssertionError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] void assertion_failed(const char* expr, const char* file, int line,
                                   const std::string& note);

}  // namespace qm

#define QM_ASSERT(expr)                                              \
  do {                                                               \
    if (!(expr)) ::qm::assertion_failed(#expr, __FILE__, __LINE__, ""); \
  } while (0)

#define QM_ASSERT_MSG(expr, note)                                       \
  do {                                                                  \
    if (!(expr)) ::qm::assertion_failed(#expr, __FILE__, __LINE__, note); \
  } while (0)
