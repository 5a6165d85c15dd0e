#include "cable_dynamics/ros/stop_request.h"

#include <pthread.h>

#include <csignal>
#include <thread>

#include <ros/callback_queue.h>
#include <ros/ros.h>

namespace cable_dynamics {
namespace {

// Written by the signal handler, read by the spinner: sig_atomic_t is the type that is safe in both.
volatile std::sig_atomic_t g_stop = 0;

}  // namespace

void installStopOnSigint() {
  // SIGINT blocked in this thread and so in every thread started after it (roscpp's, at the first
  // NodeHandle), and taken by one thread of its own with sigwait: delivered to a thread blocked in a
  // call to the master, it broke the XML-RPC client's select() (EINTR), which printed "[setParam] Failed
  // to contact master ... Retrying..." as an ERROR before it reconnected (the demo's Ctrl-C, seen in CI).
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread([set] {
    int signal = 0;
    while (sigwait(&set, &signal) == 0) {
      if (signal == SIGINT) {
        g_stop = 1;  // a later Ctrl-C stays blocked: roslaunch escalates to SIGTERM if the stop hangs
        return;
      }
    }
  }).detach();
}

void spinUntilStopped() {
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  // 0.1 s at most between a SIGINT and the shutdown, as roscpp's own handler.
  while (!stopRequested()) queue.callAvailable(ros::WallDuration(0.1));
  ros::shutdown();  // here, between callbacks: none is calling the master
}

bool stopRequested() { return g_stop != 0 || ros::isShuttingDown() || !ros::ok(); }

}  // namespace cable_dynamics
