#include "cable_dynamics/simulation/winch.h"

#include <algorithm>
#include <cmath>

#include "cable_dynamics/params/input_gate.h"

namespace cable_dynamics {
namespace {

/// A target length this close is reached [m].
constexpr double kArrived = 1e-6;

}  // namespace

Winch::Winch(const WinchParams& params) : params_(params) { reset(params.min_length); }

void Winch::reset(double length) {
  restart(length);
  next_command_ = 0;
  commandSpeed(params_.speed);
}

void Winch::restart(double length) {
  now_ = WinchMotion{length, 0.0, 0.0};
  step_start_ = 0.0;
}

void Winch::commandSpeed(double speed) {
  checkWinchSpeed(speed, params_);  // refused, never clamped
  to_length_ = false;
  speed_command_ = speed;
}

void Winch::commandLength(double length) {
  checkWinchLength(length, params_);
  to_length_ = true;
  length_command_ = length;
}

void Winch::followSchedule(double t) {
  while (next_command_ < params_.schedule.size() && params_.schedule[next_command_].time <= t) {
    const WinchCommand& c = params_.schedule[next_command_++];
    if (c.to_length) {
      commandLength(c.value);
    } else {
      commandSpeed(c.value);
    }
  }
}

double Winch::desiredSpeed(double h) const {
  const double a = params_.max_acceleration, length = now_.length, speed = now_.speed;
  // The fastest speed at the end of this step from which the winch still stops within `distance` [m]
  // ahead at its acceleration limit, counting what this step covers at its mean speed (v + v_end) h/2:
  // v_end^2 / (2a) + (v + v_end) h / 2 <= distance, with v the speed now towards the stop.
  const auto stopping = [a, h](double distance, double toward) {
    const double room = distance - 0.5 * h * toward;
    return room > 0.0 ? a * (-0.5 * h + std::sqrt(0.25 * h * h + 2.0 * room / a)) : 0.0;
  };
  double desired = speed_command_;
  if (to_length_) {
    const double error = length_command_ - length;
    // Within kArrived of the target: stop there (the law below would land on it with some speed left,
    // and then chatter around it).
    desired = std::abs(error) < kArrived
                  ? 0.0
                  : std::copysign(std::min(params_.max_speed, stopping(std::abs(error), std::copysign(speed, error))), error);
  }
  return std::clamp(desired, -stopping(length - params_.min_length, -speed),
                    stopping(params_.max_length - length, speed));
}

bool Winch::plan(double t, double h) {
  step_start_ = t;
  const double before = now_.acceleration;
  // Reaches the desired speed at the step's end when the limit allows: at a target or a length limit
  // the speed falls to zero there, with no hunting around it.
  const double acceleration =
      std::clamp((desiredSpeed(h) - now_.speed) / h, -params_.max_acceleration, params_.max_acceleration);
  now_.acceleration = acceleration;
  return acceleration != before;
}

WinchMotion Winch::at(double t) const {
  const double tau = t - step_start_;
  WinchMotion m;
  m.acceleration = now_.acceleration;
  m.speed = now_.speed + now_.acceleration * tau;
  m.length = now_.length + (now_.speed + 0.5 * now_.acceleration * tau) * tau;
  return m;
}

void Winch::finish(double t) {
  const double acceleration = now_.acceleration;
  now_ = at(t);
  now_.acceleration = acceleration;
  step_start_ = t;
}

}  // namespace cable_dynamics
