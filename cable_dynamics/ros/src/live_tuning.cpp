#include "cable_dynamics/ros/live_tuning.h"

#include <stdexcept>
#include <string>

#include "cable_dynamics/ros/stop_request.h"

namespace cable_dynamics {
namespace {

/// The generated config's field of parameter `name` (cfg/Tuning.cfg) of type T; throws when the cfg has none.
template <class T>
T TuningConfig::*fieldOf(const std::string& name) {
  for (const TuningConfig::AbstractParamDescriptionConstPtr& d : TuningConfig::__getParamDescriptions__()) {
    if (d->name != name) continue;
    const auto typed = boost::dynamic_pointer_cast<const TuningConfig::ParamDescription<T>>(d);
    if (typed) return typed->field;
  }
  throw std::logic_error("cfg/Tuning.cfg has no parameter " + name + " of the type kTunableParameters gives it");
}

// The values move between the generated config and TunableValues by kTunableParameters (tuning_checks.h):
// one list of tunable keys.

TunableValues fromConfig(const TuningConfig& c) {
  TunableValues v;
  for (const TunableParameter& t : kTunableParameters) {
    if (t.at != nullptr) {
      t.at(v) = c.*fieldOf<double>(t.name);
    } else {
      v.paused = c.*fieldOf<bool>(t.name);
    }
  }
  return v;
}

void toConfig(const TunableValues& values, TuningConfig& c) {
  TunableValues v = values;
  for (const TunableParameter& t : kTunableParameters) {
    if (t.at != nullptr) {
      c.*fieldOf<double>(t.name) = t.at(v);
    } else {
      c.*fieldOf<bool>(t.name) = v.paused;
    }
  }
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
  // Showing sets parameters on the master, which a Ctrl-C stops together with this node (stop_request.h).
  if (stopRequested()) return;
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
