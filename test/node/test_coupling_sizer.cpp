// Issue 26: the coupling sized for the pose exchange (CouplingSizer): the closed-form bounds k = 0.25 m / tau^2
// and c = 0.5 m / tau at the delay tau = exchange period + the node's period, capped by the configured
// coupling; the exchange period measured from stamps (the 90 % quantile: the slow exchanges), robust to
// stalls; no chasing of jitter.
#include <cmath>

#include <gtest/gtest.h>

#include "cable_dynamics/ros/coupling_sizer.h"

using cable_dynamics::CouplingSizer;

namespace {

/// Feeds `count` stamps `period` apart from `start` (+ `jitter` alternately); true if any resized.
bool feed(CouplingSizer& sizer, ros::Time& t, double period, int count, double jitter = 0.0) {
  bool resized = false;
  for (int i = 0; i < count; ++i) {
    t += ros::Duration(period + ((i % 2) ? jitter : -jitter));
    resized = sizer.observe(t) || resized;
  }
  return resized;
}

}  // namespace

TEST(CouplingSizer, StartsSizedForAnExchangeAtTheNodesRate) {
  CouplingSizer sizer(20000.0, 2000.0, 5.0, 0.01);  // 100 Hz node: tau = 0.02 s
  EXPECT_NEAR(sizer.stiffness(), 0.25 * 5.0 / (0.02 * 0.02), 1e-9);  // 3125 N/m
  EXPECT_NEAR(sizer.damping(), 0.5 * 5.0 / 0.02, 1e-9);              // 125 N s/m
}

TEST(CouplingSizer, FollowsTheMeasuredExchangeAndNeverExceedsTheConfiguredCoupling) {
  CouplingSizer sizer(20000.0, 2000.0, 5.0, 0.01);
  ros::Time t(100.0);
  EXPECT_TRUE(feed(sizer, t, 0.05, 20, 0.004));  // 20 Hz with +-4 ms jitter: tau = 0.06 s
  EXPECT_NEAR(sizer.exchangePeriod(), 0.054, 1e-9);  // the slow intervals' 90 % quantile
  EXPECT_NEAR(sizer.stiffness(), 0.25 * 5.0 / std::pow(sizer.delay(), 2), 1e-9);
  EXPECT_NEAR(sizer.damping(), 0.5 * 5.0 / sizer.delay(), 1e-9);
  // Jitter alone does not resize (the hysteresis is +25 % / -50 % of the delay).
  EXPECT_FALSE(feed(sizer, t, 0.05, 50, 0.006));
  // 1 kHz: the bound exceeds the configured coupling, which caps it.
  CouplingSizer stiff(2000.0, 50.0, 5.0, 0.001);
  ros::Time u(5.0);
  feed(stiff, u, 0.001, 30);
  EXPECT_EQ(stiff.stiffness(), 2000.0);
  EXPECT_EQ(stiff.damping(), 50.0);
}

TEST(CouplingSizer, IgnoresStallsAndReversedStamps) {
  CouplingSizer sizer(20000.0, 2000.0, 5.0, 0.01);
  ros::Time t(100.0);
  feed(sizer, t, 0.01, 20);
  const double k = sizer.stiffness();
  t += ros::Duration(5.0);  // a stalled stream: not its rate
  sizer.observe(t);
  t -= ros::Duration(0.5);  // a stamp from the past
  sizer.observe(t);
  feed(sizer, t, 0.01, 3);
  EXPECT_NEAR(sizer.exchangePeriod(), 0.01, 1e-6);
  EXPECT_EQ(sizer.stiffness(), k);
}

TEST(CouplingSizer, ATunedCouplingIsTheNewCap) {
  CouplingSizer sizer(20000.0, 2000.0, 5.0, 0.01);
  sizer.setConfigured(1000.0, 80.0);
  EXPECT_EQ(sizer.stiffness(), 1000.0);
  EXPECT_EQ(sizer.damping(), 80.0);
}
