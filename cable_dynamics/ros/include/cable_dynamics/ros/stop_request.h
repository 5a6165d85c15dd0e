#pragma once

namespace cable_dynamics {

/// A clean stop on SIGINT (Ctrl-C, or roslaunch stopping its nodes) for the standalone node.
///
/// roscpp's own handler asks for shutdown, and roscpp's internal thread then runs ros::shutdown()
/// within 0.1 s, concurrently with whatever callback the spinner thread is in. A callback that was calling
/// the master at that moment (the tuning server sets its parameters when a topic changes a tuned value)
/// saw the node's XML-RPC client shut under it and printed "[setParam] Failed to contact master ...
/// Retrying..." as an ERROR on the user's screen (1 stop in 12 of the demo, measured).
///
/// So the node takes SIGINT itself instead (ros::init_options::NoSigintHandler): it only records the
/// stop; spinUntilStopped() runs the callbacks until then and shuts ROS down from the spinner thread itself,
/// between callbacks. Code that talks to the master also checks stopRequested() first. SIGINT is blocked
/// in every thread but one that waits for it (sigwait): a signal delivered to a thread in a master call
/// broke its select() with EINTR, and the client printed the same ERROR before reconnecting (CI, 2026-12-03).
/// Call it after ros::init and before the first NodeHandle (roscpp's threads inherit the signal mask).
void installStopOnSigint();

/// Runs the global callback queue's callbacks until SIGINT or ros::shutdown(), then shuts ROS down.
void spinUntilStopped();

/// True once SIGINT has arrived (installStopOnSigint), or once roscpp is shutting down.
bool stopRequested();

}  // namespace cable_dynamics
