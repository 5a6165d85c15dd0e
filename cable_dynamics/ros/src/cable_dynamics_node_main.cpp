// cable_dynamics_node: simulates one umbilical; parameters from the private namespace (docs/NODE.md).
#include <ros/ros.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/ros/cable_node.h"
#include "cable_dynamics/ros/stop_request.h"

int main(int argc, char** argv) {
  // Our SIGINT handler in place of roscpp's: it records a Ctrl-C at once (stop_request.h).
  ros::init(argc, argv, "cable_dynamics_node", ros::init_options::NoSigintHandler);
  cable_dynamics::installStopOnSigint();
  ros::NodeHandle nh, private_nh("~");
  try {
    cable_dynamics::CableNode node(nh, private_nh);
    cable_dynamics::spinUntilStopped();
  } catch (const std::invalid_argument& e) {  // ConfigError too: a bad or missing parameter
    ROS_FATAL_STREAM("cable_dynamics_node: bad parameter in " << private_nh.getNamespace() << ": " << e.what());
    return 2;
  } catch (const std::runtime_error& e) {  // initial.mode: equilibrium without an equilibrium
    ROS_FATAL_STREAM("cable_dynamics_node: cannot start in " << private_nh.getNamespace() << ": " << e.what());
    return 2;
  }
  return 0;
}
