#pragma once
/// \file
/// \brief The outcome of guarding one input message, and which counter it goes to.

namespace cable_dynamics {

/// Why an input was taken or refused. The checks run in this order and the first that fails decides
/// (docs/NODE.md, "The input guard", lists the rules).
enum class InputVerdict {
  kAccepted,     ///< used
  kReacquired,   ///< used: the tracker gave up the old stream and took a consistent new one
  kNonFinite,    ///< a NaN or an infinity in any number of the message (rejected)
  kOutOfRange,   ///< a position component beyond kMaxInputPosition, a current component above kMaxCurrentSpeed
                 ///< (params/input_gate.h), a winch speed
                 ///< beyond winch.max_speed (rejected)
  kBadFrame,     ///< an invalid frame name, or one tf2 cannot place in the world frame (rejected)
  kStale,        ///< stamped more than input_timeout before or after the receiver's clock (stale)
  kOutOfOrder,   ///< stamped no later than the last accepted message of the topic (rejected)
  kImplausible,  ///< a pose too far from the cable (rejected, never followed)
  kJump,         ///< a pose that implies moving faster than kMaxInputSpeed (rejected)
  kNoWinch,      ///< a winch command, but no winch is configured (rejected)
};

/// true for the verdicts that let the message through.
inline bool isAccepted(InputVerdict v) { return v == InputVerdict::kAccepted || v == InputVerdict::kReacquired; }
/// true for the verdict counted as stale (every other refusal counts as rejected).
inline bool isStale(InputVerdict v) { return v == InputVerdict::kStale; }

/// Short English description, for logs.
inline const char* describe(InputVerdict v) {
  switch (v) {
    case InputVerdict::kAccepted: return "accepted";
    case InputVerdict::kReacquired: return "accepted as a new stream (re-acquired)";
    case InputVerdict::kNonFinite: return "has a non-finite value";
    case InputVerdict::kOutOfRange: return "is out of range";
    case InputVerdict::kBadFrame: return "has a frame that cannot be placed in the world frame";
    case InputVerdict::kStale: return "is stamped too far from now";
    case InputVerdict::kOutOfOrder: return "is not newer than the last accepted one";
    case InputVerdict::kImplausible: return "is too far from the cable (beyond twice its length and 10 m from the base)";
    case InputVerdict::kJump: return "jumps faster than the speed limit";
    case InputVerdict::kNoWinch: return "commands a winch, but no winch is configured (config key winch:)";
  }
  return "?";
}

}  // namespace cable_dynamics
