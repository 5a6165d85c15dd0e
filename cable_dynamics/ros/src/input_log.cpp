#include "cable_dynamics/ros/input_log.h"

#include <ros/console.h>

namespace cable_dynamics {
namespace {

/// Seconds between two log lines of one kind: inputs arrive at up to kHz rates.
constexpr double kLogPeriod = 5.0;

}  // namespace

void logInput(const char* topic, InputVerdict verdict, const InputCounters& c, const NodeOptions& options) {
  // One throttled call site per reason: a flood of one kind of bad input gives one line per period.
  switch (verdict) {
    case InputVerdict::kNonFinite:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s: ignored (%u rejected so far)", topic, describe(verdict),
                        c.rejected);
      break;
    case InputVerdict::kOutOfRange:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s (|position component| <= %g m, |current component| <= %g m/s): ignored (%u "
                        "rejected so far)", topic, describe(verdict), kMaxInputPosition, kMaxCurrentSpeed, c.rejected);
      break;
    case InputVerdict::kBadFrame:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s '%s' (frame names have no leading '/'): ignored (%u "
                        "rejected so far)", topic, describe(verdict), options.world_frame.c_str(), c.rejected);
      break;
    case InputVerdict::kStale:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s (more than %.3f s before or after now): ignored (%u stale "
                        "so far)", topic, describe(verdict), options.input_timeout, c.stale);
      break;
    case InputVerdict::kOutOfOrder:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s: ignored (%u rejected so far)", topic, describe(verdict),
                        c.rejected);
      break;
    case InputVerdict::kImplausible:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s: ignored (%u rejected so far)", topic, describe(verdict),
                        c.rejected);
      break;
    case InputVerdict::kJump:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s (%g m/s): ignored (%u rejected so far)", topic,
                        describe(verdict), kMaxInputSpeed, c.rejected);
      break;
    case InputVerdict::kNoWinch:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s %s: ignored (%u rejected so far)", topic, describe(verdict),
                        c.rejected);
      break;
    case InputVerdict::kAccepted:
      break;
    case InputVerdict::kReacquired:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: %s: %d consistent poses away from the tracked one: following "
                        "the new stream", topic, kReacquireAfter);
      break;
  }
}

void logWinchSpeed(InputVerdict verdict, const InputCounters& c, double max_speed) {
  // Call sites of their own: a flood of winch commands does not silence the pose and current lines.
  switch (verdict) {
    case InputVerdict::kNoWinch:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: winch/speed %s: ignored (%u rejected so far)", describe(verdict),
                        c.rejected);
      break;
    case InputVerdict::kNonFinite:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: winch/speed %s: ignored, the winch keeps its last command (%u "
                        "rejected so far)", describe(verdict), c.rejected);
      break;
    case InputVerdict::kOutOfRange:
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: winch/speed is beyond winch.max_speed (|speed| <= %g m/s): "
                        "ignored, not clamped; the winch keeps its last command (%u rejected so far)", max_speed,
                        c.rejected);
      break;
    default:
      break;
  }
}

}  // namespace cable_dynamics
