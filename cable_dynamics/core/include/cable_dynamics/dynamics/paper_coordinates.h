#pragma once
/// \file
/// \brief Between the singularity-free state (link axes, vertical twists, angular velocities) and the
///        paper's coordinates (elevation, relative azimuth, relative torsion per joint) and their rates.

#include <Eigen/Core>

#include "cable_dynamics/dynamics/azimuth_tracker.h"
#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

/// Paper coordinates q (3n) [rad] and rates qd (3n) [rad/s] of the state x of n links; each azimuth
/// continues from the tracker's (a link straight down keeps its tracked azimuth: there only psi + phi is
/// defined, and its rotation about the vertical is all counted as torsion).
void paperCoordinates(int links, const AzimuthTracker& azimuths, const Eigen::VectorXd& x, Eigen::VectorXd& q,
                      Eigen::VectorXd& qd);

/// The state (size StateLayout::size(n), energies zero) of paper coordinates q and rates qd (3n each).
void stateFromPaper(int links, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& x);

/// Moves the tracker to the state's azimuths (unwrapped against it), after each accepted step.
void followAzimuths(int links, const Eigen::VectorXd& x, AzimuthTracker& azimuths, int first = 0);

}  // namespace cable_dynamics
