// A cone set's shared ordering (map_ordering.h) offered ahead of need on an idle
// worker thread (core/parallel.h IdleWork): the work runs whole or not at all,
// never with one worker thread, and the permutation the maps get is the one they
// would have computed themselves, computed once.
#include "libquadmesh/cones/internal/ordered_cholesky.h"
#include "libquadmesh/cones/map_ordering.h"
#include "libquadmesh/core/parallel.h"
#include "tests/support/grid_system.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

using namespace qm;
using qm::test::grid_system;

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Waits up to `seconds` for `flag`.
bool wait_for(const std::atomic<bool>& flag, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!flag && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return flag;
}

}  // namespace

TEST_CASE("idle work: with one worker thread it is never offered, so never run") {
  const ThreadLimit one(1);
  std::atomic<int> runs{0};
  IdleWork work([&] { ++runs; });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK_FALSE(work.withdraw());
  CHECK(runs == 0);
  CHECK_FALSE(work.withdraw());  // a second withdraw changes nothing
}

TEST_CASE("idle work: withdrawn while every other worker thread is busy, it never runs") {
  const ThreadLimit two(2);
  std::atomic<bool> other_busy{false}, released{false};
  std::atomic<std::thread::id> other{};
  std::atomic<int> runs{0};
  bool checked = false, ran = true;
  parallel_for_index(2, [&](std::size_t i) {
    if (i == 1) {  // the other thread, kept busy until the work is withdrawn
      other = std::this_thread::get_id();
      other_busy = true;
      wait_for(released, 5.0);
      return;
    }
    // (both indices on one thread: no other thread to keep busy, nothing to check)
    if (!wait_for(other_busy, 2.0) || other.load() == std::this_thread::get_id()) return;
    IdleWork work([&] { ++runs; });
    ran = work.withdraw();
    checked = true;
    released = true;
  });
  released = true;
  if (checked) {
    CHECK_FALSE(ran);
    CHECK(runs == 0);
  }
}

TEST_CASE("idle work: withdrawn, it has run whole or not at all, and never after") {
  const ThreadLimit two(2);
  for (int trial = 0; trial < 20; ++trial) {
    std::atomic<int> begun{0}, ended{0};
    bool ran = false;
    {
      IdleWork work([&] {
        ++begun;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        ++ended;
      });
      std::this_thread::sleep_for(std::chrono::microseconds(100 * (trial % 5)));
      ran = work.withdraw();
      CHECK(begun == ended);
      CHECK(ended == (ran ? 1 : 0));
    }
    CHECK(begun == (ran ? 1 : 0));  // (destroyed: nothing ran after the withdraw)
  }
}

TEST_CASE("idle work: a worker thread with nothing else to do takes it while the offering thread works") {
  if (std::thread::hardware_concurrency() < 2) return;  // (no second core to take it)
  const ThreadLimit two(2);
  std::atomic<bool> done{false};
  IdleWork work([&] { done = true; });
  CHECK(wait_for(done, 10.0));  // the offering thread never waits on it
  CHECK(work.withdraw());
}

TEST_CASE("map ordering: the nested dissection offered is the one a map asks for, computed once") {
  const SparseMatrix H = grid_system(30);
  const std::vector<int> alone = OrderedCholesky().analyse_by_nested_dissection(H);
  REQUIRE(alone.size() == 900);
  for (std::size_t threads : {1, 2}) {
    const ThreadLimit limit(threads);
    std::atomic<int> orders{0};
    const auto order = [&] {
      ++orders;
      return OrderedCholesky().analyse_by_nested_dissection(H);
    };
    MapOrdering ordering;
    ordering.offer_nested_dissection(order);
    ordering.offer_nested_dissection(order);  // (once per cone set: a second offer is ignored)
    const std::vector<int>& asked = ordering.nested_dissection(order);
    CHECK(asked == alone);
    CHECK(ordering.has_nested_dissection());
    CHECK(orders == 1);
  }
}

TEST_CASE("map ordering: an offered ordering that fails is computed again, and fails, when asked") {
  const ThreadLimit two(2);
  std::atomic<int> orders{0};
  const auto failing = [&]() -> std::vector<int> {
    ++orders;
    throw std::runtime_error("no ordering");
  };
  MapOrdering ordering;
  ordering.offer_nested_dissection(failing);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK_THROWS_AS(ordering.nested_dissection(failing), std::runtime_error);
  CHECK_FALSE(ordering.has_nested_dissection());
  CHECK(orders >= 1);
  CHECK(orders <= 2);
}
