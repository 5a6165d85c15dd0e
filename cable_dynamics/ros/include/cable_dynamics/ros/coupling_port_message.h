#pragma once
/// \file
/// \brief rov_coupling: the ROV's port of an attached load (SimulationSnapshot::port) as a message, for an ROV
///        simulator that couples implicitly (docs/ROV_COUPLING.md).

#include <Eigen/Core>
#include <cable_msgs/CouplingPort.h>
#include <ros/time.h>

#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// Fills `msg` from the snapshot's port (paper axes; portInWorldAxes turns it): the point in the world frame (the base's rest position at
/// `base_position` [m]), the wrench and its 6x6 stiffness and damping row-major. No allocation (fixed arrays).
void fillCouplingPort(const CouplingPort& paper, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                      cable_msgs::CouplingPort& msg);

/// Every number of the message finite.
bool allFinite(const cable_msgs::CouplingPort& msg);

}  // namespace cable_dynamics
