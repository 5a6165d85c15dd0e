#pragma once
/// \file
/// \brief The winch at the base: the deployed length over time under a speed or a target-length command,
///        within speed, acceleration and length limits. Knows nothing of links (winch_links.h does).

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The deployed length and its rates at one instant.
struct WinchMotion {
  double length = 0.0;        ///< deployed length [m]
  double speed = 0.0;         ///< pay-out speed, + paying out [m/s]
  double acceleration = 0.0;  ///< [m/s^2]
};

/// A winch driven step by step: plan() fixes a constant acceleration for the coming step (so the length
/// is a quadratic in time within it, which the time scheme's stages read exactly through at()), finish()
/// moves to the step's end. The acceleration is the one that reaches the commanded speed within the
/// step, limited to +-max_acceleration; the commanded speed is limited to +-max_speed, to what can still
/// stop at min_length and max_length, and, for a target length, to what stops at the target.
class Winch {
 public:
  explicit Winch(const WinchParams& params);

  /// Back to the configured start: `length` deployed [m], at rest, the configured speed commanded.
  void reset(double length);
  /// `length` deployed [m], at rest, the command kept (recovery after a divergence).
  void restart(double length);
  /// `length` deployed [m] at the present speed and command (the cable put at rest around a running winch:
  /// reset to equilibrium must not stop it faster than max_acceleration allows).
  void moveTo(double length) {
    now_.length = length;
    now_.acceleration = 0.0;
  }
  /// Pay out (> 0) or haul in (< 0) at `speed` [m/s]; throws std::invalid_argument (params/input_gate.h)
  /// beyond +-max_speed or not finite, changing nothing (never clamped).
  void commandSpeed(double speed);
  /// Drive to the deployed length `length` [m] and stop there; throws std::invalid_argument outside
  /// [min_length, max_length] or not finite.
  void commandLength(double length);
  /// Applies the schedule's command for time t [s], if one starts at or before t and was not applied.
  void followSchedule(double t);
  /// Drops the schedule's commands not applied yet: an operator's command replaces the schedule (until
  /// reset(), which starts it again from its first command).
  void cancelSchedule() { next_command_ = params_.schedule.size(); }

  /// Fixes the acceleration for the step [t, t + h] [s]. Returns true when it differs from the last
  /// step's (a time scheme must not reuse an evaluation across the change).
  bool plan(double t, double h);
  /// The motion at time t within the planned step [s].
  WinchMotion at(double t) const;
  /// Moves to the end of the planned step, time t [s].
  void finish(double t);

  const WinchMotion& motion() const { return now_; }
  bool targeting() const { return to_length_; }
  double commandedSpeed() const { return speed_command_; }
  double targetLength() const { return length_command_; }
  const WinchParams& params() const { return params_; }

 private:
  /// The speed to reach by the end of a step of h [s] [m/s].
  double desiredSpeed(double h) const;

  WinchParams params_;
  WinchMotion now_;                 ///< at the start of the planned step
  double step_start_ = 0.0;         ///< [s]
  bool to_length_ = false;
  double speed_command_ = 0.0;      ///< [m/s]
  double length_command_ = 0.0;     ///< [m]
  std::size_t next_command_ = 0;    ///< schedule entries applied so far
};

}  // namespace cable_dynamics
