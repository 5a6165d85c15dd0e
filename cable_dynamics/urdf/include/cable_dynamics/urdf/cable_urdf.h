#pragma once
/// \file
/// \brief The cable as a URDF (urdfdom): a link per cable link with its cylinder and inertia, and per
///        joint three continuous joints about z, x, z named as in the JointState
///        (`<prefix>joint_K_azimuth`, `_elevation`, `_torsion`) with two massless frames between them.
///
/// The URDF's joints are the z-x-z angles of each link relative to the one before it (what TF carries);
/// the JointState holds the paper's coordinates, whose elevation is absolute. Use TF, not
/// robot_state_publisher, to place the links.

#include <string>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// Frame names used by the URDF and by TF.
struct CableFrameNames {
  std::string prefix;  ///< e.g. "umbilical/"
  std::string paper() const { return prefix + "cable_paper"; }
  std::string link(int k) const { return prefix + "link_" + std::to_string(k); }  ///< k = 1..n
  std::string afterAzimuth(int k) const { return prefix + "link_" + std::to_string(k) + "_azimuth"; }
  std::string afterElevation(int k) const { return prefix + "link_" + std::to_string(k) + "_elevation"; }
  std::string load() const { return prefix + "cable_load"; }
  std::string vessel() const { return prefix + "vessel"; }  ///< at the vessel's origin, its axes
  std::string rov() const { return prefix + "rov"; }        ///< at the ROV's origin, its axes
  std::string joint(int index) const { return prefix + coordinateName(index); }  ///< index 0..3n-1
};

/// URDF text of the cable (root link: the paper frame). Throws std::runtime_error if urdfdom fails.
std::string cableUrdf(const LinkProperties& properties, const CableFrameNames& names);

}  // namespace cable_dynamics
