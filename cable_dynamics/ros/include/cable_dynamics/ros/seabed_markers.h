#pragma once
/// \file
/// \brief rviz markers of the seabed: the bottom itself (a plane, or the bathymetry grid as a triangle
///        mesh), published once and latched, and the links lying on it, published with the other outputs.

#include <string>

#include <Eigen/Core>
#include <visualization_msgs/Marker.h>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// The bottom in `world_frame`, the cable's base rest position at `base_position` [m]: a flat seabed as a
/// thin box reaching 1.5 cable lengths around the base, a grid as two triangles per cell. Sand-coloured,
/// half transparent, so the cable on it stays visible.
visualization_msgs::Marker seabedMarker(const CableParams& params, const std::string& world_frame,
                                        const Eigen::Vector3d& base_position);

/// A sphere list sized once for n links (no allocation while filling it).
visualization_msgs::Marker contactMarker(const CableParams& params, const std::string& world_frame);

/// The centres of the links the seabed pushes on (normal force > 0), world frame [m].
void fillContactMarker(const SimulationSnapshot& snapshot, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                       visualization_msgs::Marker& marker);

}  // namespace cable_dynamics
