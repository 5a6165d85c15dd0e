#pragma once
/// \file
/// \brief The dynamic_reconfigure server of live tuning (cfg/Tuning.cfg) at `<node>/tuning`: it
///        translates the generated config to TunableValues and back, hands a request to the node and
///        reports the values the node has in force (a refused value comes back as the old one).

#include <functional>
#include <memory>

#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/server.h>
#include <ros/node_handle.h>

#include "cable_dynamics/TuningConfig.h"
#include "cable_dynamics/ros/tuning_checks.h"

namespace cable_dynamics {

class LiveTuning {
 public:
  /// Applies what it can of `wanted` (`levels`: the TuningLevel bits that changed) and returns the values
  /// in force afterwards.
  using Apply = std::function<TunableValues(const TunableValues& wanted, unsigned levels)>;

  /// Starts the server in `nh`'s namespace, showing `initial` (the node's values, not the cfg's defaults,
  /// and not what an earlier run left on the parameter server).
  LiveTuning(const ros::NodeHandle& nh, const TunableValues& initial, Apply apply);

  /// Shows values changed elsewhere (the set_paused service) without calling the node back. Once the node
  /// is stopping (stopRequested()) they are kept but not sent: the master may already be gone.
  void show(const TunableValues& values);

 private:
  void onRequest(TuningConfig& config, uint32_t levels);

  boost::recursive_mutex mutex_;
  dynamic_reconfigure::Server<TuningConfig> server_;
  Apply apply_;
  bool started_ = false;  ///< the first callback (setCallback's) only reports the values in force
  TunableValues in_force_;
};

}  // namespace cable_dynamics
