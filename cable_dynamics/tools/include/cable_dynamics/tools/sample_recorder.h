#pragma once
/// \file
/// \brief An output of cable_sim besides its CSV, written at the same sample times (the rosbag of
///        cable_dynamics/tools/bag/: the node's topics). An interface, so that the offline tools' library
///        stays free of ROS and only the cable_sim executable links the ROS message layer.

#include <functional>
#include <memory>
#include <string>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// Receives the simulator at every sample time (t = 0 first) and writes what it reads of it.
class SampleRecorder {
 public:
  virtual ~SampleRecorder() = default;
  /// Records the simulator's present instant. Returns false, with the reason in `error`, when it could not
  /// (a non-finite output, a write error); nothing of that instant is recorded then.
  virtual bool record(CableSimulator& sim, std::string& error) = 0;
  /// Finishes the output (a bag's index); false with the reason in `error`.
  virtual bool close(std::string& error) = 0;
};

/// Opens a recorder writing to `path` for a simulator of `params`; throws std::runtime_error naming the path
/// when it cannot.
using SampleRecorderFactory =
    std::function<std::unique_ptr<SampleRecorder>(const std::string& path, const CableParams& params)>;

}  // namespace cable_dynamics
