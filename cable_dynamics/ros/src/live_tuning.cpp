#include "cable_dynamics/ros/live_tuning.h"

namespace cable_dynamics {
namespace {

TunableValues fromConfig(const TuningConfig& c) {
  TunableValues v;
  v.current = Eigen::Vector3d(c.current_x, c.current_y, c.current_z);
  v.drag_normal = c.drag_normal;
  v.drag_tangential = c.drag_tangential;
  v.added_mass = c.added_mass;
  v.coupling_stiffness = c.coupling_stiffness;
  v.coupling_damping = c.coupling_damping;
  v.rate = c.rate;
  v.paused = c.paused;
  v.winch_speed = c.winch_speed;
  return v;
}

void toConfig(const TunableValues& v, TuningConfig& c) {
  c.current_x = v.current.x();
  c.current_y = v.current.y();
  c.current_z = v.current.z();
  c.drag_normal = v.drag_normal;
  c.drag_tangential = v.drag_tangential;
  c.added_mass = v.added_mass;
  c.coupling_stiffness = v.coupling_stiffness;
  c.coupling_damping = v.coupling_damping;
  c.rate = v.rate;
  c.paused = v.paused;
  c.winch_speed = v.winch_speed;
}

}  // namespace

LiveTuning::LiveTuning(const ros::NodeHandle& nh, const TunableValues& initial, Apply apply)
    : server_(mutex_, nh), apply_(std::move(apply)), in_force_(initial) {
  TuningConfig config;
  toConfig(initial, config);
  server_.updateConfig(config);  // replaces what the server read from the parameter server
  server_.setCallback([this](TuningConfig& c, uint32_t levels) { onRequest(c, levels); });
}

void LiveTuning::show(const TunableValues& values) {
  in_force_ = values;
  TuningConfig config;
  toConfig(values, config);
  server_.updateConfig(config);
}

void LiveTuning::onRequest(TuningConfig& config, uint32_t levels) {
  if (started_) in_force_ = apply_(fromConfig(config), levels);
  started_ = true;
  toConfig(in_force_, config);  // what the server stores and replies: the values in force
}

}  // namespace cable_dynamics
