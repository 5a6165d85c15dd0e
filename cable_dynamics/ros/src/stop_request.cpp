#include "cable_dynamics/ros/stop_request.h"

#include <csignal>

#include <ros/callback_queue.h>
#include <ros/ros.h>

namespace cable_dynamics {
namespace {

// Written by the signal handler, read by the spinner: sig_atomic_t is the type that is safe in both.
volatile std::sig_atomic_t g_stop = 0;

void onSigint(int) { g_stop = 1; }

}  // namespace

void installStopOnSigint() { std::signal(SIGINT, onSigint); }

void spinUntilStopped() {
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  // 0.1 s at most between a SIGINT and the shutdown, as roscpp's own handler.
  while (!stopRequested()) queue.callAvailable(ros::WallDuration(0.1));
  ros::shutdown();  // here, between callbacks: none is calling the master
}

bool stopRequested() { return g_stop != 0 || ros::isShuttingDown() || !ros::ok(); }

}  // namespace cable_dynamics
