#pragma once
/// \file
/// \brief Adds and removes links at the winch as the deployed length passes whole links: the winch's
///        link (the base link) stays between 1 and 2.25 configured link lengths (docs/MODEL.md section 8).

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_dynamics.h"

namespace cable_dynamics {

/// The band the winch's link is kept in, in configured link lengths: longer than kSplitAt, it splits
/// into a link of the configured length and a new winch's link; shorter than kMergeAt, it merges into
/// the next link. After either, it is a quarter of a link from the other bound, so that a winch that
/// reverses does not add and remove the same link step after step.
constexpr double kWinchLinkSplitAt = 2.25;
constexpr double kWinchLinkMergeAt = 1.0;

/// What a regrid would do now: add a link (the winch's link longer than kWinchLinkSplitAt links and a
/// slot left on the drum), remove one (shorter than kWinchLinkMergeAt and a link beyond it to merge
/// into), or nothing.
enum class WinchRegrid { kNone, kAdded, kRemoved };
WinchRegrid winchRegridDue(const ChainDeployment& deployed, double winch_length, double link_length);

/// After an accepted step, with `winch_length` [m] the winch's link's length now and `link_length`
/// [m] the configured length of a link added at the winch: splits the winch's link (a new slot in
/// front of it takes the winch's part, with the same axis, twist and angular velocity: the cable's
/// shape, velocity field and energy do not change) or merges it into the next link (one straight link
/// of their summed length along their chord, with the far end's velocity kept: mass and length are
/// kept, the kink between the two is lost). Updates the state x and the dynamics' deployed slots, and
/// `outboard_length` [m], the deployed length beyond the winch's link. No allocation.
WinchRegrid regridWinchLinks(ChainDynamics& dynamics, Eigen::VectorXd& x, double winch_length, double link_length,
                             double winch_speed, double& outboard_length);

}  // namespace cable_dynamics
