#include "cable_dynamics/ros/sim_clock.h"

#include <algorithm>

namespace cable_dynamics {

void SimClock::anchor(const ros::Time& now, double sim_time) {
  anchored_ = true;
  anchor_ros_ = now;
  anchor_sim_ = sim_time;
}

double SimClock::lag(const ros::Time& now, double sim_time) const {
  return std::max(0.0, dueSimTime(now) - sim_time);
}

double SimClock::dropExcessLag(const ros::Time& now, double sim_time) {
  const double excess = lag(now, sim_time) - max_lag_;
  if (excess <= 0.0) return 0.0;
  anchor_ros_ += ros::Duration(excess);  // the same simulated instant now stands for a later ROS time
  return excess;
}

}  // namespace cable_dynamics
