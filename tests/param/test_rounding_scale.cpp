// The scale chosen where the periods round best (param/rounding_scale.h).
#include "libquadmesh/param/rounding_scale.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

TEST_CASE("rounding residual: the squared distances of s p_k to their integers") {
  CHECK(rounding_residual({}, 1.0) == 0.0);
  CHECK(rounding_residual({3.0, -7.0}, 1.0) == doctest::Approx(0.0));
  // 0.25 and 0.4 from their integers, the 0.3 period rounds away from 0 (rule 4)
  CHECK(rounding_residual({2.25, -5.4, 0.3}, 1.0) == doctest::Approx(0.0625 + 0.16 + 0.49));
  CHECK(rounding_residual({2.25}, 2.0) == doctest::Approx(0.25));
}

TEST_CASE("rounding scale: the best rounding within the window, nearest the requested scale") {
  // already integers: the requested scale stays
  CHECK(rounding_scale({12.0, -30.0}, 1.0, 0.03) == 1.0);
  // no period or no window: nothing to choose
  CHECK(rounding_scale({}, 2.0, 0.03) == 2.0);
  CHECK(rounding_scale({12.5}, 1.0, 0.0) == 1.0);
  // 20.5 is half a cell off at s = 1; 20 / 20.5 and 21 / 20.5 are 2.4% away
  const double s = rounding_scale({20.5}, 1.0, 0.03);
  CHECK(rounding_residual({20.5}, s) < 1e-4);
  CHECK(std::abs(s - 1.0) == doctest::Approx(0.5 / 20.5).epsilon(1e-2));
  // several incommensurate periods (a plate's two holes and two bridges, 0.29 to
  // 0.46 off at the requested scale): never worse than any scale of the window,
  // sampled 20 times more finely
  const std::vector<double> plate{-38.71, -26.46, -12.54, -6.59};
  const double s0 = 1.0;
  const double chosen = rounding_scale(plate, s0, 0.03);
  CHECK(std::abs(chosen - s0) <= 0.03 * s0 + 1e-12);
  double finest = rounding_residual(plate, s0);
  for (int i = -20000; i <= 20000; ++i) finest = std::min(finest, rounding_residual(plate, s0 * (1 + 0.03 * i / 20000.0)));
  CHECK(rounding_residual(plate, chosen) <= finest + 0.02);
  CHECK(rounding_residual(plate, s0) == doctest::Approx(0.6754));
  CHECK(rounding_residual(plate, chosen) < 0.25 * rounding_residual(plate, s0));
}
