#include "cable_dynamics/ros/rate_window.h"

namespace cable_dynamics {

void RateWindow::restart(const ros::WallTime& start) {
  start_ = start;
  started_ = true;
  simulated_ = 0.0;
  cycles_ = steps_ = retried_ = 0;
}

void RateWindow::add(const ros::WallTime& now, double simulated, long steps, long retried) {
  if (!started_) restart(now);
  simulated_ += simulated;
  ++cycles_;
  steps_ += steps;
  retried_ += retried;
  const double wall = (now - start_).toSec();
  if (wall < length_) return;
  real_time_factor_ = simulated_ / wall;
  loop_rate_ = cycles_ / wall;
  retried_share_ = steps_ > 0 ? static_cast<double>(retried_) / steps_ : 0.0;
  restart(now);
}

}  // namespace cable_dynamics
