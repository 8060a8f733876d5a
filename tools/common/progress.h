// Progress lines on stderr, one per pipeline stage: "[  0.42 s] reading input".
#pragma once

#include <chrono>
#include <string>

namespace qm::tools {

class Progress {
 public:
  explicit Progress(bool quiet) : quiet_(quiet), start_(std::chrono::steady_clock::now()) {}
  /// Announces a stage (nothing when quiet).
  void stage(const std::string& what) const;
  /// Seconds since construction.
  double elapsed() const;

 private:
  bool quiet_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace qm::tools
