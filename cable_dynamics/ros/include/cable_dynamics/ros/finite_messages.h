#pragma once
/// \file
/// \brief The last check before publishing: true when every number of a message is finite.

#include <vector>

#include <cable_msgs/CableState.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/MarkerArray.h>

#include "cable_dynamics/ros/message_builders.h"

namespace cable_dynamics {

bool allFinite(const sensor_msgs::JointState& msg);
bool allFinite(const std::vector<geometry_msgs::TransformStamped>& transforms);
bool allFinite(const visualization_msgs::MarkerArray& msg);
bool allFinite(const cable_msgs::CableState& msg);
bool allFinite(const geometry_msgs::WrenchStamped& msg);
/// The numbers the diagnostics are written from.
bool allFinite(const NodeStatus& status);
/// Every message of `outputs` but the diagnostics.
bool allFinite(const CableOutputs& outputs);

}  // namespace cable_dynamics
