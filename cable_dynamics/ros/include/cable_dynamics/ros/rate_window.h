#pragma once
/// \file
/// \brief Rates measured over a window of wall time: real-time factor (simulated seconds per wall
///        second), loop rate, and the share of steps that needed substeps.

#include <ros/time.h>

namespace cable_dynamics {

/// Accumulates cycles over at least `length` wall seconds, then publishes the rates of that window.
class RateWindow {
 public:
  explicit RateWindow(double length = 1.0) : length_(length) {}

  /// Starts a window at wall time `start`; the last rates stay readable.
  void restart(const ros::WallTime& start);
  /// One cycle that simulated `simulated` seconds in `steps` steps, `retried` of them in substeps. Closes the
  /// window when it is long enough.
  void add(const ros::WallTime& now, double simulated, long steps, long retried);

  double realTimeFactor() const { return real_time_factor_; }  ///< simulated s per wall s, last window [-]
  double loopRate() const { return loop_rate_; }                ///< cycles per wall second, last window [Hz]
  double retriedShare() const { return retried_share_; }        ///< steps needing substeps, last window [-]

 private:
  double length_;
  ros::WallTime start_;
  bool started_ = false;
  double simulated_ = 0.0;
  long cycles_ = 0, steps_ = 0, retried_ = 0;
  double real_time_factor_ = 0.0, loop_rate_ = 0.0, retried_share_ = 0.0;
};

}  // namespace cable_dynamics
