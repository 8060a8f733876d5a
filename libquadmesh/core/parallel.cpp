#include "libquadmesh/core/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <atomic>

namespace qm {

void parallel_for_index(std::size_t n, const std::function<void(std::size_t)>& body) {
  if (n == 0) return;
  if (worker_threads() <= 1 || n == 1) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
  });
}

struct ThreadLimit::Impl {
  std::unique_ptr<tbb::global_control> control;
};

ThreadLimit::ThreadLimit(std::size_t threads) : impl_(std::make_unique<Impl>()) {
  if (threads > 0)
    impl_->control =
        std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
}

ThreadLimit::~ThreadLimit() = default;

struct IdleWork::Impl {
  enum State { offered, started, withdrawn };
  std::function<void()> work;
  std::atomic<int> state{offered};  // started: a thread took it (it has ended once withdraw() waited)
  tbb::task_group group;
};

IdleWork::IdleWork(std::function<void()> work) : impl_(std::make_unique<Impl>()) {
  impl_->work = std::move(work);
  if (worker_threads() <= 1) {
    impl_->state = Impl::withdrawn;
    return;
  }
  // the task waits in the offering thread's queue; another thread that runs out
  // of work takes it, and the offering thread, waiting in withdraw(), finds it
  // withdrawn
  Impl* impl = impl_.get();
  impl_->group.run([impl] {
    int expected = Impl::offered;
    if (!impl->state.compare_exchange_strong(expected, Impl::started)) return;
    impl->work();
  });
}

IdleWork::~IdleWork() { withdraw(); }

bool IdleWork::withdraw() {
  int expected = Impl::offered;
  impl_->state.compare_exchange_strong(expected, Impl::withdrawn);
  impl_->group.wait();
  return impl_->state == Impl::started;
}

std::size_t worker_threads() {
  return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
}

}  // namespace qm
