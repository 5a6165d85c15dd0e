// The azimuth tracker (turn counting, no trigonometry per step) against the nearest-branch unwrapping
// it replaces, psi += atan2(sin(d), cos(d)) with d = atan2(x, y) - psi, over random walks that cross
// the branch cut many times, and on the cut itself (x = +0 and x = -0).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cable_dynamics/dynamics/azimuth_tracker.h"

namespace cd = cable_dynamics;

namespace {

double unwrapNearest(double psi, double x, double y) {
  const double d = std::atan2(x, y) - psi;
  return psi + std::atan2(std::sin(d), std::cos(d));
}

}  // namespace

TEST(AzimuthTracker, MatchesNearestBranchUnwrapping) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> step(-2.5, 2.5);  // [rad], below pi: the nearest branch is defined
  std::uniform_real_distribution<double> radius(0.1, 3.0);
  for (int walk = 0; walk < 20; ++walk) {
    const double start = step(rng) * 5.0;
    cd::AzimuthTracker tracker(1);
    tracker.reset(Eigen::VectorXd::Constant(1, start));
    EXPECT_NEAR(tracker.reference(0), start, 1e-12);
    double expected = start, angle = start;
    int crossings = 0;
    for (int i = 0; i < 2000; ++i) {
      angle += step(rng);
      const double r = radius(rng);
      const double x = r * std::sin(angle), y = r * std::cos(angle);
      const double before = expected;
      expected = unwrapNearest(expected, x, y);
      crossings += std::floor((before + M_PI) / (2 * M_PI)) != std::floor((expected + M_PI) / (2 * M_PI));
      tracker.follow(0, x, y);
      ASSERT_NEAR(tracker.reference(0), expected, 1e-9) << "walk " << walk << " step " << i;
    }
    EXPECT_GT(crossings, 10);  // the walk did cross the cut
  }
}

TEST(AzimuthTracker, SignedZeroOnTheCut) {
  // atan2(+0, -1) = pi and atan2(-0, -1) = -pi: the tracker counts turns the way atan2 reads the cut.
  cd::AzimuthTracker tracker(1);
  tracker.reset(Eigen::VectorXd::Constant(1, 3.0));
  tracker.follow(0, +0.0, -1.0);
  EXPECT_NEAR(tracker.reference(0), M_PI, 1e-15);
  tracker.follow(0, -0.1, -1.0);  // just past the cut, increasing
  EXPECT_NEAR(tracker.reference(0), M_PI + std::atan2(0.1, 1.0), 1e-12);
  tracker.follow(0, -0.0, -1.0);
  EXPECT_NEAR(tracker.reference(0), M_PI, 1e-15);
  tracker.follow(0, 0.1, -1.0);  // back, decreasing
  EXPECT_NEAR(tracker.reference(0), M_PI - std::atan2(0.1, 1.0), 1e-12);
}
