// Writing files so that they appear complete or not at all, alone or together.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace qm::io {

/// Files that appear together or not at all (a mesh and its report): add()
/// writes each one to a temporary file beside its destination that keeps the
/// destination's extension (writers choose formats by extension); commit()
/// renames them all onto their destinations. If a writer throws, a rename fails,
/// or the object is destroyed before commit(), every temporary file and every
/// destination already renamed is removed: none of the files is left.
class AtomicFiles {
 public:
  AtomicFiles() = default;
  AtomicFiles(const AtomicFiles&) = delete;
  AtomicFiles& operator=(const AtomicFiles&) = delete;
  ~AtomicFiles();

  /// Calls write(temporary); throws qm::Error(bad_input) naming `path` if the
  /// writer produced no data (after removing everything, as above).
  void add(const std::string& path, const std::function<void(const std::string&)>& write);
  /// Renames every file onto its destination; throws qm::Error(bad_input) naming
  /// the destination that failed (after removing everything, as above).
  void commit();

 private:
  struct Pending {
    std::string path, temporary;
  };
  void discard() noexcept;
  std::vector<Pending> pending_;
  std::vector<std::string> renamed_;
  bool committed_ = false;
};

/// One file: AtomicFiles with a single add() and commit(). If write throws, the
/// temporary file is removed and the exception propagates; nothing is left at `path`.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace qm::io
