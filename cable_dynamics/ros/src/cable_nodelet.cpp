// cable_dynamics/CableNodelet: the node's CableNode inside a nodelet manager (e.g. an ROV simulator's
// process), so that its subscribers there receive the messages without serialization or copies.
#include <memory>
#include <stdexcept>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "cable_dynamics/ros/cable_node.h"

namespace cable_dynamics {

class CableNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    // The single-threaded handles: every callback of the cable (timer, inputs, services, tuning) runs
    // on one queue, as in the standalone node, so CableNode needs no locks.
    try {
      node_ = std::make_unique<CableNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& e) {
      // The manager hosts other nodelets: a bad parameter stops this cable, not the process.
      NODELET_FATAL_STREAM("cable_dynamics nodelet: bad parameter in " << getPrivateNodeHandle().getNamespace()
                           << ": " << e.what() << " (this cable does not run)");
    }
  }

  std::unique_ptr<CableNode> node_;
};

}  // namespace cable_dynamics

PLUGINLIB_EXPORT_CLASS(cable_dynamics::CableNodelet, nodelet::Nodelet)
