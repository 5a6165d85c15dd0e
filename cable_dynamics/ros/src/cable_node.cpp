#include "cable_dynamics/ros/seabed_markers.h"
#include "cable_dynamics/ros/cable_node.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <tf2_eigen/tf2_eigen.h>

#include "cable_dynamics/dynamics/paper_model.h"
#include "cable_dynamics/params/format_values.h"
#include "cable_dynamics/ros/cycle_stepper.h"
#include "cable_dynamics/ros/coupling_port_message.h"
#include "cable_dynamics/ros/coupling_sizer.h"
#include "cable_dynamics/ros/finite_messages.h"
#include "cable_dynamics/ros/input_log.h"
#include "cable_dynamics/ros/reset_request.h"
#include "cable_dynamics/ros/tuning_checks.h"
#include "cable_dynamics/ros/winch_request.h"

namespace cable_dynamics {
namespace {

/// Input messages queued per topic: large enough that a burst (or a node stalled by a busy machine for
/// a few hundred ms) loses nothing; stale ones are refused by their stamps anyway.
constexpr uint32_t kInputQueueSize = 1000;
/// Share of a cycle's period that stepping may take; the rest is for publishing [-].
constexpr double kSteppingShare = 0.8;
/// Seconds between two log lines of one kind (divergence, dropped time).
constexpr double kLogPeriod = 5.0;

const char* loadModeName(LoadMode mode) {
  return mode == LoadMode::kFree       ? "free"
         : mode == LoadMode::kAnchored ? "anchored"
         : mode == LoadMode::kAttached ? "attached"
                                       : "body";
}

}  // namespace

CableNode::CableNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh), private_nh_(private_nh), tf_listener_(tf_buffer_), clock_(1.0) {
  loadNodeParameters(private_nh_, params_, options_, &config_tree_, &ros_tree_);
  // The gate (checkSimulatorInputs) refuses a dt beyond RK4's reach and the combinations the simulator
  // cannot run, throwing ConfigError naming the key, as cable_sim and Python do.
  sim_ = std::make_unique<CableSimulator>(params_);
  params_ = sim_->params();  // the model's copy: with a winch, the drum's slots that every output has
  if (params_.load.mode == LoadMode::kAttached && options_.min_rov_mass > 0.0) {
    // The ROV feels the coupling one exchange late: sized for the lightest ROV at the exchange's delay,
    // first for an exchange at this node's own rate, then as the pose stream's stamps measure it.
    sizer_ = std::make_unique<CouplingSizer>(params_.load.coupling_stiffness, params_.load.coupling_damping,
                                             options_.min_rov_mass, 1.0 / options_.rate);
    applyCouplingSize();
  }
  names_.prefix = options_.frame_prefix;
  clock_ = SimClock(options_.max_lag);

  GuardSettings guard;
  guard.world_frame = options_.world_frame;
  guard.input_timeout = options_.input_timeout;
  guard.base_rest = options_.base_position;
  guard.plausible_radius = 2.0 * params_.totalLength() + 10.0;  // an ROV beyond it cannot be on this cable
  guard.rov_attachment = params_.load.attachment;
  guard.base_hang_off = params_.base.hang_off;
  guard.winch = params_.winch.enabled;
  guard.winch_max_speed = params_.winch.max_speed;
  guard_ = std::make_unique<InputGuard>(guard);
  resolver_ = [this](const std::string& frame, Eigen::Isometry3d& t) { return resolveFrame(frame, t); };

  ROS_INFO_STREAM("cable_dynamics: " << params_.links << " links, " << params_.totalLength() << " m, diameter "
                                     << params_.diameter << " m, " << params_.mass_per_length << " kg/m, load "
                                     << params_.load.mass << " kg (" << loadModeName(params_.load.mode)
                                     << "), fluid density " << params_.fluid.density << " kg/m^3, integrator "
                                     << integratorName(params_.simulation.integrator) << ", dt " << params_.simulation.dt
                                     << " s, rate " << options_.rate << " Hz, world frame '" << options_.world_frame
                                     << "', frame prefix '" << options_.frame_prefix << "', input timeout "
                                     << options_.input_timeout << " s, at most " << stepsPerCycleCap(options_, sim_->dt())
                                     << " steps per cycle, max lag " << options_.max_lag
                                     << " s; recommended RK4 step " << sim_->estimateStableTimeStep()
                                     << " s (half its estimated stability limit, or less where accuracy needs it: a chain released in air)");
  const double per_cycle = stepsPerCycleCap(options_, sim_->dt()) * sim_->dt();  // [s] of simulated time
  if (per_cycle * options_.rate < 1.0) {
    ROS_WARN_STREAM("cable_dynamics: ros.max_steps_per_cycle = " << options_.max_steps_per_cycle << " steps of "
                    << sim_->dt() << " s simulate at most " << per_cycle << " s per " << 1.0 / options_.rate
                    << " s cycle: the node cannot keep real time (real-time factor at most " << per_cycle * options_.rate
                    << "); leave the key out for a cap that can");
  }
  if (params_.winch.enabled) {
    const WinchParams& w = params_.winch;
    ROS_INFO_STREAM("cable_dynamics: winch at the base: " << sim_->deployedLength() << " m deployed in "
                    << params_.links - sim_->firstLink() << " links, length " << w.min_length << " to "
                    << w.max_length << " m (" << params_.links << " slots of " << w.link_length << " m), at most "
                    << w.max_speed << " m/s and " << w.max_acceleration << " m/s^2; commands on winch/speed "
                    << "(std_msgs/Float64, m/s, + pays out) and the winch/set_length service");
  }

  // The URDF describes every slot at its configured length (with a winch: the longest deployment), one
  // fixed model while links come off and go back onto the drum: a slot on the drum (zero length and mass
  // in the simulator) is in it at the length and mass it has once paid out.
  nh_.setParam("robot_description", cableUrdf(deriveLinkProperties(params_), names_));
  prepareOutputs(params_, names_, options_.world_frame, outputs_, options_.shapes);
  source_.spring_force = Eigen::VectorXd::Zero(3 * params_.links);

  joint_pub_.advertise(nh_, "joint_states", 10);
  state_pub_.advertise(nh_, "cable_state", 10);
  marker_pub_.advertise(nh_, "cable_markers", 2);
  wrench_pub_.advertise(nh_, "rov_wrench", 10);
  wrench_world_pub_.advertise(nh_, "rov_wrench_world", 10);
  base_wrench_pub_.advertise(nh_, "base_wrench", 10);
  base_wrench_world_pub_.advertise(nh_, "base_wrench_world", 10);
  if (params_.load.mode == LoadMode::kAttached) {
    port_pub_.advertise(nh_, "rov_coupling", 10);
    port_msg_.header.frame_id = options_.world_frame;
  }
  if (params_.seabed.enabled) {
    // The bottom once, latched (a late rviz still gets it); the links on it with every output.
    seabed_pub_ = nh_.advertise<visualization_msgs::Marker>("seabed_marker", 1, true);
    seabed_pub_.publish(seabedMarker(params_, options_.world_frame, options_.base_position));
    contact_pub_ = nh_.advertise<visualization_msgs::Marker>("seabed_contact_marker", 2);
    contact_marker_ = contactMarker(params_, options_.world_frame);
  }
  if (params_.load.mode == LoadMode::kBody) {
    // The ROV is simulated here: thrust (body frame) and the station keeper's target in, odometry out.
    odom_pub_.advertise(nh_, "rov_odom", 10);
    thrust_sub_ = nh_.subscribe("rov_thrust", kInputQueueSize, &CableNode::onRovThrust, this);
    target_sub_ = nh_.subscribe("rov_target", kInputQueueSize, &CableNode::onRovTarget, this);
  }
  diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 5);
  rov_sub_ = nh_.subscribe("rov_pose", kInputQueueSize, &CableNode::onRovPose, this);
  base_sub_ = nh_.subscribe("base_pose", kInputQueueSize, &CableNode::onBasePose, this);
  current_sub_ = nh_.subscribe("current", kInputQueueSize, &CableNode::onCurrent, this);
  // Also without a winch: its commands are then refused (counted, logged, the service says why).
  winch_sub_ = nh_.subscribe("winch/speed", kInputQueueSize, &CableNode::onWinchSpeed, this);
  winch_srv_ = nh_.advertiseService("winch/set_length", &CableNode::onSetWinchLength, this);
  reset_srv_ = nh_.advertiseService("reset", &CableNode::onReset, this);
  equilibrium_srv_ = nh_.advertiseService("reset_to_equilibrium", &CableNode::onResetToEquilibrium, this);
  model_srv_ = nh_.advertiseService("get_model", &CableNode::onGetModel, this);
  pause_srv_ = nh_.advertiseService("set_paused", &CableNode::onSetPaused, this);
  tuned_ = tunableValuesOf(params_, options_.rate);
  tuning_ = std::make_unique<LiveTuning>(ros::NodeHandle(private_nh_, "tuning"), tuned_,
                                         [this](const TunableValues& wanted, unsigned levels) {
                                           return applyTuning(wanted, levels);
                                         });
  timer_ = nh_.createTimer(ros::Duration(1.0 / options_.rate), &CableNode::onTimer, this);
}

bool CableNode::currentTopicActive() const {
  return !last_current_accepted_.isZero() &&
         std::abs((ros::Time::now() - last_current_accepted_).toSec()) <= options_.input_timeout;
}

TunableValues CableNode::applyTuning(const TunableValues& wanted, unsigned levels) {
  // Each part on its own: one refused value does not hold back the others of the same request.
  const auto refused = [this](const char* part, const std::string& why) {
    ++status_.refused_commands;
    ROS_WARN_STREAM("cable_dynamics: tuning: " << part << " refused, the old value stays: " << why);
  };
  if (levels & kTuneCurrent) {
    try {
      checkTunedCurrent(wanted.current);
      if (currentTopicActive()) {
        throw std::invalid_argument("the current topic publishes (a message accepted within ros.input_timeout = " +
                                    formatNumber(options_.input_timeout) + " s): it sets the current");
      }
      sim_->setCurrent(wanted.current);
      tuned_.current = wanted.current;
      current_tuned_ = true;
      ROS_INFO_STREAM("cable_dynamics: tuning: current [" << wanted.current.transpose() << "] m/s");
    } catch (const std::invalid_argument& e) {
      refused("current", e.what());
    }
  }
  if (levels & kTuneCoefficients) {
    try {
      YAML::Node tree;
      const CableParams tuned = tunedParams(config_tree_, wanted, tree);  // ConfigError: key, value, range
      CableParams running = tuned;  // the coupling as the exchange allows it (CouplingSizer)
      if (sizer_) {
        sizer_->setConfigured(tuned.load.coupling_stiffness, tuned.load.coupling_damping);
        running.load.coupling_stiffness = sizer_->stiffness();
        running.load.coupling_damping = sizer_->damping();
      }
      sim_->retune(running);  // RK4's stable step too; rebuilds the chain's constants between two cycles
      params_ = tuned;
      adoptTree(config_tree_, tree);
      TunableValues given = wanted;
      std::ostringstream text;
      for (const TunableParameter& t : kTunableParameters) {
        if (t.level != kTuneCoefficients) continue;
        t.at(tuned_) = t.at(given);
        text << (text.tellp() > 0 ? ", " : "") << t.key << " " << t.at(given);
      }
      ROS_INFO_STREAM("cable_dynamics: tuning: " << text.str());
    } catch (const std::invalid_argument& e) {
      refused("coefficients", e.what());
    }
  }
  if (levels & kTuneRate) {
    try {
      checkTunedRate(ros_tree_, wanted.rate);
      YAML::Node ros_tree = ros_tree_.IsMap() ? YAML::Clone(ros_tree_) : YAML::Node(YAML::NodeType::Map);
      ros_tree["rate"] = wanted.rate;
      adoptTree(ros_tree_, ros_tree);
      options_.rate = wanted.rate;
      tuned_.rate = wanted.rate;
      timer_.setPeriod(ros::Duration(1.0 / wanted.rate));
      ROS_INFO_STREAM("cable_dynamics: tuning: rate " << wanted.rate << " Hz");
    } catch (const std::invalid_argument& e) {
      refused("rate", e.what());
    }
  }
  if (levels & kTunePause) setPaused(wanted.paused);
  if (levels & kTuneWinch) {
    std::string why;
    if (checkTunedWinchSpeed(wanted.winch_speed, params_.winch, why)) {
      if (sim_->hasWinch()) sim_->commandWinchSpeed(wanted.winch_speed);
      tuned_.winch_speed = wanted.winch_speed;
      ROS_INFO_STREAM("cable_dynamics: tuning: winch speed " << wanted.winch_speed << " m/s");
    } else {
      refused("winch_speed", why);
    }
  }
  return tuned_;
}

void CableNode::setPaused(bool paused) {
  if (status_.paused && !paused) restartClock();  // resume where it stopped: the pause is not simulated
  status_.paused = paused;
  tuned_.paused = paused;
}

bool CableNode::resolveFrame(const std::string& frame, Eigen::Isometry3d& world_from_frame) {
  // canTransform first: lookupTransform would throw (and tf2 may log) for every unknown frame.
  if (!tf_buffer_.canTransform(options_.world_frame, frame, ros::Time(0), nullptr)) return false;
  try {
    world_from_frame = tf2::transformToEigen(tf_buffer_.lookupTransform(options_.world_frame, frame, ros::Time(0)));
  } catch (const tf2::TransformException&) {
    return false;
  }
  return true;
}

void CableNode::onRovPose(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  Eigen::Vector3d position, velocity;
  Eigen::Quaterniond attitude;
  const InputVerdict verdict =
      guard_->pose(InputGuard::kRovPose, *msg, ros::Time::now(), resolver_, position, velocity, attitude);
  logInput("rov_pose", verdict, guard_->counters(), options_);
  if (!isAccepted(verdict)) return;
  if (sizer_ && sizer_->observe(msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp)) {
    applyCouplingSize();
  }
  // The attachment point at the simulated instant its stamp stands for: between poses the simulator
  // carries it on with the pose stream's velocity (a first-order hold; docs/ROV_COUPLING.md).
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  const double at = clock_.anchored() ? clock_.dueSimTime(stamp) : sim_->time();
  sim_->setLoadTarget(position - options_.base_position, velocity, attitude, at);
  // Live by its stamp, not by when the callback ran: a queue that lags must not make old poses look live.
  last_rov_pose_ = {true, position - options_.base_position, attitude, stamp};
  if (params_.load.mode == LoadMode::kFree) {
    ROS_WARN_ONCE("cable_dynamics: rov_pose received but load.mode is free: the pose is ignored (use attached)");
  }
  if (params_.load.mode == LoadMode::kBody) {
    ROS_WARN_ONCE("cable_dynamics: rov_pose received but load.mode is body: the ROV is simulated here and the "
                  "pose is ignored (rov_target moves its station keeper's target)");
  }
}

void CableNode::applyCouplingSize() {
  CableParams running = params_;
  running.load.coupling_stiffness = sizer_->stiffness();
  running.load.coupling_damping = sizer_->damping();
  sim_->retune(running);  // between cycles: rebuilds the chain's constants aside (allocates; not in a step)
  ROS_INFO_STREAM("cable_dynamics: coupling sized for a " << options_.min_rov_mass << " kg ROV (ros.min_rov_mass) "
                  << "exchanging poses every " << sizer_->exchangePeriod() << " s with this node's " << 1.0 / options_.rate
                  << " s cycles: " << sizer_->stiffness() << " N/m, " << sizer_->damping() << " N s/m (configured "
                  << params_.load.coupling_stiffness << " N/m, " << params_.load.coupling_damping << " N s/m)");
}

void CableNode::onBasePose(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  Eigen::Vector3d position, velocity;
  Eigen::Quaterniond attitude;
  const InputVerdict verdict =
      guard_->pose(InputGuard::kBasePose, *msg, ros::Time::now(), resolver_, position, velocity, attitude);
  logInput("base_pose", verdict, guard_->counters(), options_);
  // The hang-off point, relative to where it is at rest (ros.base_position).
  if (!isAccepted(verdict)) return;
  sim_->setBaseTarget(position - options_.base_position, velocity, attitude);
  last_base_pose_ = {true, position - options_.base_position, attitude,
                     msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp};
}

void CableNode::restoreLivePoses() {
  const ros::Time now = ros::Time::now();
  const auto live = [&](const HeldPose& p) {
    return p.known && std::abs((now - p.received).toSec()) <= options_.input_timeout;
  };
  if (live(last_base_pose_)) {
    sim_->setBaseTarget(last_base_pose_.position, Eigen::Vector3d::Zero(), last_base_pose_.attitude);
  }
  if (live(last_rov_pose_) && params_.load.mode != LoadMode::kBody) {
    sim_->setLoadTarget(last_rov_pose_.position, Eigen::Vector3d::Zero(), last_rov_pose_.attitude, sim_->time());
  }
}

void CableNode::onCurrent(const geometry_msgs::TwistStamped::ConstPtr& msg) {
  Eigen::Vector3d current;
  const InputVerdict verdict = guard_->current(*msg, ros::Time::now(), resolver_, current);
  logInput("current", verdict, guard_->counters(), options_);
  if (!isAccepted(verdict)) return;
  sim_->setCurrent(current);
  last_current_accepted_ = ros::Time::now();
  // The tuning server shows the current in force: the topic's while it publishes (issue 27).
  const bool changed = current != tuned_.current;
  tuned_.current = current;
  showInForce(changed);
}

void CableNode::showInForce(bool changed) {
  show_pending_ = show_pending_ || changed;
  if (!show_pending_ || (ros::WallTime::now() - last_show_).toSec() < kShowPeriod) return;
  tuning_->show(tuned_);
  last_show_ = ros::WallTime::now();
  show_pending_ = false;
}

void CableNode::onWinchSpeed(const std_msgs::Float64::ConstPtr& msg) {
  double speed = 0.0;
  const InputVerdict verdict = guard_->winchSpeed(*msg, speed);
  logWinchSpeed(verdict, guard_->counters(), params_.winch.max_speed);
  if (!isAccepted(verdict)) return;
  sim_->commandWinchSpeed(speed);  // the last command wins, the topic's or the tuning's
  const bool changed = speed != tuned_.winch_speed;
  tuned_.winch_speed = speed;
  showInForce(changed);
}

bool CableNode::onSetWinchLength(cable_msgs::SetWinchLength::Request& req,
                                 cable_msgs::SetWinchLength::Response& res) {
  res.deployed_length = sim_->deployedLength();
  if (!checkWinchLength(req.length, params_.winch, res.message)) {
    ++status_.refused_commands;
    res.success = false;
    ROS_WARN_STREAM_THROTTLE(kLogPeriod, "cable_dynamics: winch/set_length: " << res.message);
    return true;
  }
  sim_->commandWinchLength(req.length);
  res.success = true;
  std::ostringstream s;
  s << "winch driving from " << res.deployed_length << " m to " << req.length << " m (at most "
    << params_.winch.max_speed << " m/s)";
  res.message = s.str();
  return true;
}

void CableNode::recoverFromDivergence(const std::string& why) {
  ++status_.diverged;
  ROS_ERROR_STREAM_THROTTLE(kLogPeriod, "cable_dynamics: " << why << "; cable recovered to its initial shape, time "
                                                           << "and inputs carry on (" << status_.diverged
                                                           << " divergences so far)");
  sim_->recover();
}

void CableNode::restartClock() { clock_.anchor(ros::Time::now(), sim_->time()); }

void CableNode::onRovThrust(const geometry_msgs::WrenchStamped::ConstPtr& msg) {
  Eigen::Vector3d force, torque;
  std::string why;
  ++body_received_;
  if (!readThrust(*msg, names_.rov(), force, torque, why)) {
    ++thrust_rejected_;
    ROS_WARN_STREAM_THROTTLE(kLogPeriod, "cable_dynamics: rov_thrust rejected (" << thrust_rejected_ << " so far): " << why);
    return;
  }
  sim_->setBodyThrust(force, torque);
  last_thrust_ = ros::Time::now();
  thrust_held_ = true;
}

void CableNode::onRovTarget(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  Eigen::Vector3d position;
  Eigen::Quaterniond attitude;
  std::string why;
  ++body_received_;
  if (!readBodyTarget(*msg, options_.world_frame, options_.base_position, position, attitude, why)) {
    ++target_rejected_;
    ROS_WARN_STREAM_THROTTLE(kLogPeriod, "cable_dynamics: rov_target rejected (" << target_rejected_ << " so far): " << why);
    return;
  }
  sim_->setBodyTarget(position, attitude);
}

void CableNode::dropStaleThrust(const ros::Time& now) {
  if (!thrust_held_ || std::abs((now - last_thrust_).toSec()) <= options_.input_timeout) return;
  sim_->setBodyThrust(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  thrust_held_ = false;
  ++thrust_stale_;
  ROS_WARN_STREAM("cable_dynamics: rov_thrust silent for more than ros.input_timeout = " << options_.input_timeout
                  << " s: thrust set to zero (" << thrust_stale_ << " times so far)");
}

void CableNode::onTimer(const ros::TimerEvent&) {
  const ros::Time now = ros::Time::now();
  if (params_.load.mode == LoadMode::kBody) dropStaleThrust(now);
  showInForce(false);  // a topic's last change, if its show was held back
  const ros::WallTime wall_start = ros::WallTime::now();
  if (!clock_.anchored() || now < last_now_) {  // first cycle, or the clock jumped back (/clock restarted)
    clock_.anchor(now, sim_->time());
    last_stamp_ = ros::Time();
    last_diagnostics_ = now;
  }
  last_now_ = now;
  const double sim_before = sim_->time();
  CycleReport cycle;
  if (status_.paused) {
    clock_.anchor(now, sim_->time());  // paused time is not simulated
  } else {
    // Whole steps up to the clock, bounded by a count and by wall time; the rest is lag, made up later
    // unless it exceeds ros.max_lag.
    const double due = (clock_.dueSimTime(now) - sim_->time()) / sim_->dt();
    const long wanted = std::clamp<long>(static_cast<long>(std::floor(due + 1e-9)), 0, stepsPerCycleCap(options_, sim_->dt()));
    cycle = stepCycle(*sim_, wanted, wall_start + ros::WallDuration(kSteppingShare / options_.rate));
    status_.retried += static_cast<unsigned>(cycle.retried);
    if (cycle.diverged) {
      ++status_.diverged;
      ROS_ERROR_STREAM_THROTTLE(kLogPeriod, "cable_dynamics: " << cycle.message << "; cable recovered to its initial "
                                << "shape, time and inputs carry on (" << status_.diverged << " divergences so far)");
    }
    const double dropped = clock_.dropExcessLag(now, sim_->time());
    if (dropped > 0.0) {
      status_.dropped_time += dropped;
      ROS_WARN_THROTTLE(kLogPeriod, "cable_dynamics: more than %.3f s behind the clock: %.3f s of simulated time "
                        "dropped so far (real-time factor %.3f)", options_.max_lag, status_.dropped_time,
                        window_.realTimeFactor());
    }
  }
  status_.step_time = (ros::WallTime::now() - wall_start).toSec();
  status_.lag = clock_.lag(now, sim_->time());
  window_.add(ros::WallTime::now(), std::max(0.0, sim_->time() - sim_before), cycle.steps, cycle.retried);

  // Everything is stamped with the ROS time of the simulated instant; TF refuses a repeated stamp, so an
  // instant is published once (a cycle that took no step publishes nothing new).
  const ros::Time stamp = clock_.stampOf(sim_->time());
  if (stamp > last_stamp_) publishOutputs(stamp);

  if ((now - last_diagnostics_).toSec() >= options_.diagnostics_period) {
    status_.diverged_recently = status_.diverged > diverged_at_diagnostics_;
    status_.dropped_recently = status_.dropped_time > dropped_at_diagnostics_;
    diverged_at_diagnostics_ = status_.diverged;
    dropped_at_diagnostics_ = status_.dropped_time;
    if (allFinite(status_)) {
      fillDiagnostics(status_, now, outputs_.diagnostics);
      diagnostics_pub_.publish(outputs_.diagnostics);
    }
    last_diagnostics_ = now;
  }
}

void CableNode::publishOutputs(const ros::Time& stamp) {
  if (!readOutputs(*sim_, source_)) {
    recoverFromDivergence("non-finite state at t = " + formatNumber(sim_->time()) + " s (nothing published)");
    return;
  }
  const InputCounters& inputs = guard_->counters();
  status_.sim_time = sim_->time();
  status_.real_time_factor = window_.realTimeFactor();
  status_.loop_rate = window_.loopRate();
  status_.retried_share = window_.retriedShare();
  status_.energy_error = std::max(sim_->energyDrift(), sim_->energyRise());
  // The ROV body's inputs (rov_thrust, rov_target) count with the guarded streams' in cable_state.
  status_.received = inputs.received + static_cast<unsigned>(body_received_);
  status_.rejected = inputs.rejected + static_cast<unsigned>(thrust_rejected_ + target_rejected_);
  status_.stale = inputs.stale;
  max_tension_seen_ = std::max(max_tension_seen_, source_.snapshot.chain.tension.maxCoeff());
  const double scale = options_.tension_scale > 0.0 ? options_.tension_scale : max_tension_seen_;

  status_.winch = winchStatus(source_);
  status_.slack_links = static_cast<unsigned>(source_.snapshot.chain.slack_links);
  status_.snaps = static_cast<unsigned>(source_.snapshot.snaps);
  status_.largest_tension = source_.snapshot.largest_tension;
  updateLimitStatus(source_.snapshot, status_.limits);  // counts this cycle when a limit is exceeded
  shapeOutputs(source_.snapshot.first_link, outputs_);  // the deployed links only; no allocation
  fillJointState(source_, stamp, outputs_.joints);
  fillTransforms(source_, options_.base_position, stamp, outputs_.transforms);
  fillMarkers(source_, params_.totalLength(), scale, stamp, outputs_.markers, options_.colour_by);
  fillCableState(source_, status_, stamp, outputs_.state);
  fillWrenches(source_, options_.base_position, stamp, outputs_);
  const bool attached = params_.load.mode == LoadMode::kAttached;
  if (attached) fillCouplingPort(source_.snapshot.port, options_.base_position, stamp, port_msg_);
  // Never a non-finite number out, even one derived from a finite state (an overflowing arrow).
  const bool body = params_.load.mode == LoadMode::kBody;
  if (body) fillRovOdometry(source_.snapshot, options_.base_position, stamp, options_.world_frame, names_.rov(), odom_msg_);
  const bool odom_finite = !body || (std::isfinite(odom_msg_.pose.pose.position.x + odom_msg_.pose.pose.position.y +
                                                   odom_msg_.pose.pose.position.z + odom_msg_.twist.twist.linear.x +
                                                   odom_msg_.twist.twist.linear.y + odom_msg_.twist.twist.linear.z +
                                                   odom_msg_.twist.twist.angular.x + odom_msg_.twist.twist.angular.y +
                                                   odom_msg_.twist.twist.angular.z + odom_msg_.pose.pose.orientation.w));
  if (!allFinite(outputs_) || (attached && !allFinite(port_msg_)) || !odom_finite) {
    recoverFromDivergence("non-finite output at t = " + formatNumber(sim_->time()) + " s (nothing published)");
    return;
  }
  joint_pub_.publish(outputs_.joints);
  tf_broadcaster_.sendTransform(outputs_.transforms);
  tf_broadcaster_.sendTransform(outputs_.body_transforms);
  marker_pub_.publish(outputs_.markers);
  if (params_.seabed.enabled) {
    fillContactMarker(source_.snapshot, options_.base_position, stamp, contact_marker_);
    contact_pub_.publish(contact_marker_);
  }
  state_pub_.publish(outputs_.state);
  wrench_pub_.publish(outputs_.wrench);
  wrench_world_pub_.publish(outputs_.wrench_world);
  base_wrench_pub_.publish(outputs_.base_wrench);
  base_wrench_world_pub_.publish(outputs_.base_wrench_world);
  if (attached) port_pub_.publish(port_msg_);
  if (body) odom_pub_.publish(odom_msg_);
  last_stamp_ = stamp;
}

bool CableNode::onReset(cable_msgs::Reset::Request& req, cable_msgs::Reset::Response& res) {
  if (!checkResetRequest(req.positions, req.velocities, params_.links, names_, res.message, params_.drumSlots())) {
    ++status_.refused_commands;
    res.success = false;
    return true;
  }
  try {
    // The reset on a copy first, and its first step tried on another: a state that cannot be stepped (a
    // violent one diverges even in substeps) is refused with the step's reason, and the running cable is
    // kept as it was; nothing of it is published.
    CableSimulator candidate(*sim_);
    if (req.positions.empty()) {
      candidate.reset();
    } else {
      // With a winch the shape applies to the configured deployment: the winch goes back to its start.
      if (candidate.hasWinch()) candidate.reset();
      const Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(req.positions.data(), req.positions.size());
      Eigen::VectorXd qd = Eigen::VectorXd::Zero(q.size());
      if (!req.velocities.empty()) qd = Eigen::Map<const Eigen::VectorXd>(req.velocities.data(), req.velocities.size());
      candidate.setPaperState(q, qd);
    }
    const StepReport first = candidate.trialStep();
    if (!first.ok) {
      ++status_.refused_commands;
      res.success = false;
      res.message = "refused, the cable keeps its state: the state cannot be stepped at dt = " +
                    std::to_string(candidate.dt()) + " s (" + first.message.substr(0, first.message.find("; state kept")) + ")";
      ROS_WARN_STREAM_THROTTLE(kLogPeriod, "cable_dynamics: reset " << res.message);
      return true;
    }
    *sim_ = std::move(candidate);
  } catch (const std::invalid_argument& e) {
    ++status_.refused_commands;
    res.success = false;
    res.message = e.what();
    return true;
  }
  if (sizer_) sizer_->forgetStream();  // the exchange is measured afresh (the size in force stays)
  thrust_held_ = false;                // a reset zeroes the ROV body's commanded thrust
  restoreLivePoses();
  restartClock();  // the simulator's time is 0 again
  // Tuned coefficients stay (they are the simulator's now); a tuned current is an input like the topic's
  // and comes back unless the topic publishes; the winch is back at its configured speed.
  if (current_tuned_ && !currentTopicActive()) sim_->setCurrent(tuned_.current);
  if (params_.winch.enabled && tuned_.winch_speed != params_.winch.speed) {
    tuned_.winch_speed = params_.winch.speed;
    tuning_->show(tuned_);
  }
  res.success = true;
  res.message = "reset";
  return true;
}

bool CableNode::onResetToEquilibrium(cable_msgs::ResetToEquilibrium::Request&,
                                     cable_msgs::ResetToEquilibrium::Response& res) {
  const StaticSolution s = sim_->resetToEquilibrium();
  res.success = s.converged;
  res.iterations = static_cast<uint32_t>(s.iterations);
  res.residual = s.residual;
  if (!s.converged) {
    ++status_.refused_commands;
    res.message = s.message;
    ROS_WARN_STREAM("cable_dynamics: reset_to_equilibrium refused: " << s.message);
    return true;
  }
  SimulationSnapshot snapshot;
  sim_->snapshot(snapshot);
  res.line_pull = snapshot.line_pull;
  std::ostringstream text;
  text << "at rest in the static equilibrium (" << s.iterations << " Newton iterations, residual " << s.residual
       << ", line pull " << snapshot.line_pull << " N)";
  res.message = text.str();
  return true;
}

bool CableNode::onGetModel(cable_msgs::GetModel::Request&, cable_msgs::GetModel::Response& res) {
  const int dof = 3 * sim_->links();
  Eigen::VectorXd q(dof), qd(dof);
  sim_->paperCoordinates(q, qd);
  const PaperModelTerms t = paperModelAt(sim_->properties(), q, qd);
  const auto vec = [](const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  const auto mat = [](const Eigen::MatrixXd& m) {
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> r = m;
    return std::vector<double>(r.data(), r.data() + r.size());
  };
  res.coordinates.resize(dof);
  for (int i = 0; i < dof; ++i) res.coordinates[i] = names_.joint(i);
  res.q = vec(q);
  res.qd = vec(qd);
  res.M = mat(t.M);
  res.h = vec(t.h);
  res.G = vec(t.G);
  res.K = mat(t.K);
  res.elastic = vec(t.elastic);
  res.D = mat(t.D);
  return true;
}

bool CableNode::onSetPaused(cable_msgs::SetPaused::Request& req, cable_msgs::SetPaused::Response& res) {
  setPaused(req.paused);
  tuning_->show(tuned_);
  res.success = true;
  res.message = status_.paused ? "paused" : "running";
  return true;
}

}  // namespace cable_dynamics
