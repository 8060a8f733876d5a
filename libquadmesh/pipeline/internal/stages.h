// The pipeline's stages as the user sees them: a progress line when one begins,
// and its wall-clock time (QuadMeshResult::timings) when the next one does.
#pragma once

#include "libquadmesh/pipeline/mesh_quads.h"

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace qm {

class Stages {
 public:
  /// Appends (key, seconds) to `out` as stages close; `progress` may be empty.
  Stages(std::vector<std::pair<std::string, double>>& out, const ProgressCallback& progress)
      : out_(out), progress_(progress) {}
  /// Closes the running stage (if any) and announces the next one.
  void next(const std::string& key, const std::string& message) {
    close();
    key_ = key;
    if (progress_) progress_(message);
  }
  /// Closes the running stage (if any) and says what comes next without timing it
  /// as a stage of its own (work whose stages are timed elsewhere and replayed).
  void announce(const std::string& message) {
    close();
    if (progress_) progress_(message);
  }
  /// What stages run elsewhere said and took (cone placements tried side by side,
  /// each with its own Stages): the messages in order, the timings appended (they
  /// overlap in wall-clock time with the other work run beside them).
  void replay(const std::vector<std::string>& messages, const std::vector<std::pair<std::string, double>>& timings) {
    if (progress_)
      for (const std::string& message : messages) progress_(message);
    out_.insert(out_.end(), timings.begin(), timings.end());
  }
  /// Closes the running stage (if any).
  void close() {
    const auto now = std::chrono::steady_clock::now();
    if (!key_.empty()) out_.emplace_back(key_, std::chrono::duration<double>(now - last_).count());
    key_.clear();
    last_ = now;
  }

 private:
  std::vector<std::pair<std::string, double>>& out_;
  ProgressCallback progress_;  // a copy: a caller may pass a temporary ({})
  std::string key_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace qm
