// Both cores for loops whose iterations are independent (closest-point queries
// per sample, per quad, per vertex). Each index is computed on its own and
// writes only its own slot; anything summed or maximized over the indices is
// reduced afterwards, in index order. So a result is the same bit for bit
// whatever the number of threads (issue 21: deterministic on any core count).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace qm {

/// Calls body(i) for every i in [0, n), spread over the worker threads. body
/// must write only what belongs to index i and must not throw (a throw ends the
/// program: a programmer error).
void parallel_for_index(std::size_t n, const std::function<void(std::size_t)>& body);

/// out[i] = f(i) for i in [0, n), computed by parallel_for_index.
template <class T, class F>
std::vector<T> parallel_map(std::size_t n, const F& f) {
  std::vector<T> out(n);
  parallel_for_index(n, [&](std::size_t i) { out[i] = f(i); });
  return out;
}

/// While alive, at most `threads` worker threads (1: everything on the calling
/// thread), for a command's --threads and for the tests that check the results
/// do not depend on it. 0: no limit.
class ThreadLimit {
 public:
  explicit ThreadLimit(std::size_t threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The number of worker threads loops may use now.
std::size_t worker_threads();

/// Work offered to a worker thread that has nothing else to do, for a result
/// that may be needed later (a map's ordering while the map that may need it is
/// made): it runs only where a thread takes it before withdraw(), so it never
/// delays the thread that offered it. Nothing is offered with one worker thread.
/// The work must not throw (a throw ends the program: catch inside it).
class IdleWork {
 public:
  explicit IdleWork(std::function<void()> work);
  /// withdraw()
  ~IdleWork();
  IdleWork(const IdleWork&) = delete;
  IdleWork& operator=(const IdleWork&) = delete;
  /// Takes the work back if no thread has started it, else waits until it ends.
  /// True when it ran.
  bool withdraw();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace qm
