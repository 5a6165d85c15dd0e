#include "cable_dynamics/ros/cable_node.h"

#include <algorithm>
#include <cmath>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <tf2_eigen/tf2_eigen.h>

#include "cable_dynamics/dynamics/frames.h"
#include "cable_dynamics/dynamics/paper_model.h"

namespace cable_dynamics {
namespace {

/// Half turn about x: the paper frame (z down) in the world frame (z up).
const Eigen::Quaterniond kPaperInWorld(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));

constexpr double kMaxInputSpeed = 20.0;  ///< a pose that implies a faster ROV or base is a jump [m/s]

bool finite(const geometry_msgs::Pose& p) {
  return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
         std::isfinite(p.orientation.x) && std::isfinite(p.orientation.y) && std::isfinite(p.orientation.z) &&
         std::isfinite(p.orientation.w);
}

geometry_msgs::Vector3 vectorMsg(const Eigen::Vector3d& v) {
  geometry_msgs::Vector3 m;
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
  return m;
}

void setPose(geometry_msgs::Transform& t, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  t.translation = vectorMsg(p);
  t.rotation.x = q.x();
  t.rotation.y = q.y();
  t.rotation.z = q.z();
  t.rotation.w = q.w();
}

/// Blue (slack) through green to red (the top of the scale); compression in grey.
std_msgs::ColorRGBA tensionColor(double tension, double scale) {
  std_msgs::ColorRGBA c;
  c.a = 1.0;
  if (tension < 0.0) {
    c.r = c.g = c.b = 0.6;
    return c;
  }
  const double f = std::clamp(tension / scale, 0.0, 1.0);
  c.r = static_cast<float>(std::clamp(2.0 * f - 1.0, 0.0, 1.0));
  c.g = static_cast<float>(1.0 - std::abs(2.0 * f - 1.0));
  c.b = static_cast<float>(std::clamp(1.0 - 2.0 * f, 0.0, 1.0));
  return c;
}

}  // namespace

CableNode::CableNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh), private_nh_(private_nh), tf_listener_(tf_buffer_) {
  loadNodeParameters(private_nh_, params_, options_);
  sim_ = std::make_unique<CableSimulator>(params_);  // throws std::invalid_argument on a refused combination
  joints_ = std::make_unique<ElasticJoints>(sim_->properties());
  names_.prefix = options_.frame_prefix;
  alpha_hint_ = Eigen::VectorXd::Zero(params_.links);
  effort_ = Eigen::VectorXd::Zero(3 * params_.links);

  ROS_INFO_STREAM("cable_dynamics: " << params_.links << " links, " << params_.totalLength() << " m, diameter "
                  << params_.diameter << " m, " << params_.mass_per_length << " kg/m, load " << params_.load.mass
                  << " kg (" << (params_.load.mode == LoadMode::kFree ? "free" : params_.load.mode == LoadMode::kAnchored ? "anchored" : "attached")
                  << "), fluid density " << params_.fluid.density << " kg/m^3, integrator "
                  << integratorName(params_.simulation.integrator) << ", dt " << params_.simulation.dt << " s, rate " << options_.rate
                  << " Hz, world frame '" << options_.world_frame << "', frame prefix '" << options_.frame_prefix
                  << "', input timeout " << options_.input_timeout << " s; estimated largest stable RK4 step "
                  << sim_->estimateStableTimeStep() << " s");

  nh_.setParam("robot_description", cableUrdf(sim_->properties(), names_));
  prepareMessages();

  joint_pub_ = nh_.advertise<sensor_msgs::JointState>("joint_states", 10);
  state_pub_ = nh_.advertise<cable_msgs::CableState>("cable_state", 10);
  marker_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("cable_markers", 2);
  wrench_pub_ = nh_.advertise<geometry_msgs::WrenchStamped>("rov_wrench", 10);
  diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 5);
  rov_sub_ = nh_.subscribe("rov_pose", 10, &CableNode::onRovPose, this);
  base_sub_ = nh_.subscribe("base_pose", 10, &CableNode::onBasePose, this);
  current_sub_ = nh_.subscribe("current", 10, &CableNode::onCurrent, this);
  reset_srv_ = nh_.advertiseService("reset", &CableNode::onReset, this);
  model_srv_ = nh_.advertiseService("get_model", &CableNode::onGetModel, this);
  pause_srv_ = nh_.advertiseService("set_paused", &CableNode::onSetPaused, this);
  timer_ = nh_.createTimer(ros::Duration(1.0 / options_.rate), &CableNode::onTimer, this);
}

void CableNode::prepareMessages() {
  const int n = params_.links, dof = 3 * n;
  joint_msg_.name.resize(dof);
  for (int i = 0; i < dof; ++i) joint_msg_.name[i] = names_.joint(i);
  joint_msg_.position.assign(dof, 0.0);
  joint_msg_.velocity.assign(dof, 0.0);
  joint_msg_.effort.assign(dof, 0.0);

  // TF: world -> paper frame, then every link frame, the URDF's intermediate frames, and the load.
  transforms_.resize(2 + 3 * n);
  transforms_[0].header.frame_id = options_.world_frame;
  transforms_[0].child_frame_id = names_.paper();
  for (int k = 0; k < n; ++k) {
    transforms_[1 + 3 * k].child_frame_id = names_.link(k + 1);
    transforms_[2 + 3 * k].child_frame_id = names_.afterAzimuth(k + 1);
    transforms_[3 + 3 * k].child_frame_id = names_.afterElevation(k + 1);
  }
  transforms_.back().child_frame_id = names_.load();
  for (std::size_t i = 1; i < transforms_.size(); ++i) transforms_[i].header.frame_id = names_.paper();

  // Markers: the cable coloured by tension, the load, force arrows at both ends, the colour scale.
  marker_msg_.markers.resize(5);
  const char* const kNamespaces[5] = {"cable", "load", "base_force", "load_force", "tension_scale"};
  const int kTypes[5] = {visualization_msgs::Marker::LINE_STRIP, visualization_msgs::Marker::SPHERE,
                         visualization_msgs::Marker::ARROW, visualization_msgs::Marker::ARROW,
                         visualization_msgs::Marker::TEXT_VIEW_FACING};
  for (int i = 0; i < 5; ++i) {
    visualization_msgs::Marker& m = marker_msg_.markers[i];
    m.header.frame_id = names_.paper();
    m.ns = kNamespaces[i];
    m.id = 0;
    m.type = kTypes[i];
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.color.a = 1.0;
  }
  const double width = std::max(4.0 * params_.diameter, 0.008 * params_.totalLength());
  marker_msg_.markers[0].scale.x = width;
  marker_msg_.markers[0].points.resize(n + 1);
  marker_msg_.markers[0].colors.resize(n + 1);
  const double load_size = std::max(0.5, 0.03 * params_.totalLength());
  marker_msg_.markers[1].scale.x = marker_msg_.markers[1].scale.y = marker_msg_.markers[1].scale.z = load_size;
  marker_msg_.markers[1].color.r = 1.0;
  marker_msg_.markers[1].color.g = 0.8;
  for (int i : {2, 3}) {
    marker_msg_.markers[i].points.resize(2);
    marker_msg_.markers[i].scale.x = width;        // shaft diameter
    marker_msg_.markers[i].scale.y = 2.0 * width;  // head diameter
    marker_msg_.markers[i].scale.z = 3.0 * width;  // head length
    marker_msg_.markers[i].color.r = 1.0;
    marker_msg_.markers[i].color.b = 1.0;
  }
  marker_msg_.markers[4].scale.z = std::max(0.5, 0.03 * params_.totalLength());
  marker_msg_.markers[4].color.r = marker_msg_.markers[4].color.g = marker_msg_.markers[4].color.b = 1.0;

  state_msg_.tension.assign(n, 0.0);
  state_msg_.header.frame_id = options_.world_frame;
  wrench_msg_.header.frame_id = names_.load();  // at the ROV, axes parallel to the world frame's
}

bool CableNode::fresh(const ros::Time& stamp, const char* topic) {
  // A zero stamp means "now" (publishers that do not stamp); otherwise older than the timeout is stale.
  if (stamp.isZero()) return true;
  const double age = (ros::Time::now() - stamp).toSec();
  if (age > options_.input_timeout) {
    ++stale_;
    ROS_WARN_THROTTLE(5.0, "cable_dynamics: %s is %.3f s old (timeout %.3f s): ignored (%u stale so far)", topic, age,
                      options_.input_timeout, stale_);
    return false;
  }
  return true;
}

bool CableNode::acceptPose(const geometry_msgs::PoseStamped& msg, const char* topic, Eigen::Vector3d& world) {
  if (!finite(msg.pose)) {
    ++rejected_;
    ROS_WARN_THROTTLE(5.0, "cable_dynamics: %s has a non-finite value: ignored (%u rejected so far)", topic, rejected_);
    return false;
  }
  if (!fresh(msg.header.stamp, topic)) return false;
  Eigen::Vector3d position(msg.pose.position.x, msg.pose.position.y, msg.pose.position.z);
  const std::string& frame = msg.header.frame_id;
  if (!frame.empty() && frame != options_.world_frame) {
    try {
      const geometry_msgs::TransformStamped t =
          tf_buffer_.lookupTransform(options_.world_frame, frame, ros::Time(0), ros::Duration(0.0));
      position = tf2::transformToEigen(t) * position;
    } catch (const tf2::TransformException& e) {
      ++rejected_;
      ROS_WARN_THROTTLE(5.0, "cable_dynamics: %s in frame '%s' cannot be placed in '%s' (%s): ignored", topic,
                        frame.c_str(), options_.world_frame.c_str(), e.what());
      return false;
    }
  }
  world = position;
  return true;
}

bool CableNode::trackPose(const geometry_msgs::PoseStamped& msg, const char* topic, TrackedPose& tracked) {
  Eigen::Vector3d world;
  if (!acceptPose(msg, topic, world)) return false;
  const ros::Time stamp = msg.header.stamp.isZero() ? ros::Time::now() : msg.header.stamp;
  if (tracked.valid) {
    const double dt = (stamp - tracked.stamp).toSec();
    if (dt > 1e-4) {
      const Eigen::Vector3d velocity = (world - tracked.position) / dt;
      if (velocity.norm() > kMaxInputSpeed) {
        ++rejected_;
        ROS_WARN_THROTTLE(5.0, "cable_dynamics: %s jumped %.2f m in %.3f s: ignored", topic,
                          (world - tracked.position).norm(), dt);
        return false;
      }
      tracked.velocity = velocity;
    }
  }
  tracked.valid = true;
  tracked.position = world;
  tracked.stamp = stamp;
  return true;
}

void CableNode::onRovPose(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  if (!trackPose(*msg, "rov_pose", rov_)) return;
  sim_->setLoadTarget(rov_.position - options_.base_position, rov_.velocity);
  if (params_.load.mode == LoadMode::kFree) {
    ROS_WARN_ONCE("cable_dynamics: rov_pose received but load.mode is free: the pose is ignored (use attached)");
  }
}

void CableNode::onBasePose(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  if (!trackPose(*msg, "base_pose", base_)) return;
  sim_->setBaseTarget(base_.position - options_.base_position, base_.velocity);
}

void CableNode::onCurrent(const geometry_msgs::TwistStamped::ConstPtr& msg) {
  Eigen::Vector3d current(msg->twist.linear.x, msg->twist.linear.y, msg->twist.linear.z);
  if (!current.allFinite() || current.norm() > 100.0) {
    ++rejected_;
    ROS_WARN_THROTTLE(5.0, "cable_dynamics: current is not finite or above 100 m/s: ignored (%u rejected so far)", rejected_);
    return;
  }
  if (!fresh(msg->header.stamp, "current")) return;
  const std::string& frame = msg->header.frame_id;
  if (!frame.empty() && frame != options_.world_frame) {
    try {
      const geometry_msgs::TransformStamped t =
          tf_buffer_.lookupTransform(options_.world_frame, frame, ros::Time(0), ros::Duration(0.0));
      current = tf2::transformToEigen(t).rotation() * current;  // a velocity: rotate only
    } catch (const tf2::TransformException& e) {
      ++rejected_;
      ROS_WARN_THROTTLE(5.0, "cable_dynamics: current in frame '%s' cannot be placed in '%s': ignored", frame.c_str(),
                        options_.world_frame.c_str());
      return;
    }
  }
  sim_->setCurrent(current);
}

void CableNode::resynchronize() {
  start_stamp_ = ros::Time::now();
  steps_done_ = 0;
}

void CableNode::onTimer(const ros::TimerEvent&) {
  const ros::Time now = ros::Time::now();
  if (!started_ || now < start_stamp_) {  // first cycle, or the clock jumped back (/clock restarted)
    started_ = true;
    resynchronize();
    rate_window_start_ = ros::WallTime::now();
  }
  const ros::WallTime wall_start = ros::WallTime::now();
  int steps = 0;
  if (!paused_) {
    // Catch up with the clock in whole steps, at most max_steps_per_cycle now; the rest is lag, reported
    // and made up in later cycles (simulated time is never dropped).
    const double dt = sim_->dt();
    const long due = static_cast<long>(std::floor((now - start_stamp_).toSec() / dt + 1e-9));
    const long wanted = due - steps_done_;
    const long allowed = std::min<long>(wanted, options_.max_steps_per_cycle);
    for (long i = 0; i < allowed; ++i) {
      const StepReport report = sim_->step();
      if (!report.ok) {
        ++diverged_;
        ROS_ERROR_STREAM_THROTTLE(5.0, "cable_dynamics: " << report.message << "; cable reset to its initial state ("
                                                          << diverged_ << " divergences so far)");
        sim_->reset();
        break;
      }
      ++steps;
    }
    steps_done_ += steps;
    if (steps < allowed) steps_done_ = due;  // after a reset, restart from the clock
    lag_ = std::max(0.0, (due - steps_done_) * dt);
    if (lag_ > 0.0) {
      ROS_WARN_THROTTLE(5.0, "cable_dynamics: %.3f s behind the clock (at most %d steps per cycle)", lag_,
                        options_.max_steps_per_cycle);
    }
  }
  step_seconds_ = (ros::WallTime::now() - wall_start).toSec();
  rate_window_steps_ += steps;
  ++rate_window_cycles_;
  const double window = (ros::WallTime::now() - rate_window_start_).toSec();
  if (window >= 1.0) {
    real_time_factor_ = rate_window_steps_ * sim_->dt() / window;
    loop_rate_ = rate_window_cycles_ / window;
    rate_window_steps_ = rate_window_cycles_ = 0;
    rate_window_start_ = ros::WallTime::now();
  }
  // On a coarse /clock two cycles can share a stamp; TF rejects repeated stamps, so publish once per stamp.
  if (now != last_publish_) publish(now, step_seconds_);
  last_publish_ = now;
  if ((now - last_diagnostics_).toSec() >= options_.diagnostics_period || now < last_diagnostics_) {
    publishDiagnostics(now);
    last_diagnostics_ = now;
  }
}

void CableNode::publish(const ros::Time& stamp, double step_seconds) {
  sim_->snapshot(snapshot_);
  const int n = params_.links, dof = 3 * n;
  const ChainOutputs& c = snapshot_.chain;
  // Never publish a non-finite number: a state that produced one is reset instead.
  if (!snapshot_.q.allFinite() || !snapshot_.qd.allFinite() || !c.tension.allFinite() || !c.ends.allFinite()) {
    ++diverged_;
    ROS_ERROR_THROTTLE(5.0, "cable_dynamics: non-finite output at t = %.3f s: cable reset", snapshot_.time);
    sim_->reset();
    return;
  }
  // Joint states: the paper's coordinates; effort = the joint springs' generalized torque (no dampers).
  joints_->force(snapshot_.q, effort_);
  for (int i = 0; i < dof; ++i) {
    joint_msg_.position[i] = snapshot_.q(i);
    joint_msg_.velocity[i] = snapshot_.qd(i);
    joint_msg_.effort[i] = -effort_(i);
  }
  joint_msg_.header.stamp = stamp;
  joint_pub_.publish(joint_msg_);

  // TF, one call for every frame.
  linkFrames(snapshot_.axes, snapshot_.twists, c.ends.col(0), sim_->properties().length, link_poses_, after_z_, after_x_,
             alpha_hint_);
  setPose(transforms_[0].transform, options_.base_position, kPaperInWorld);
  for (int k = 0; k < n; ++k) {
    setPose(transforms_[1 + 3 * k].transform, link_poses_[k].position, link_poses_[k].orientation);
    setPose(transforms_[2 + 3 * k].transform, after_z_[k].position, after_z_[k].orientation);
    setPose(transforms_[3 + 3 * k].transform, after_x_[k].position, after_x_[k].orientation);
  }
  // The load frame is aligned with the world frame (only translated), so the wrench reads in world axes.
  setPose(transforms_.back().transform, c.ends.col(n), kPaperInWorld.conjugate());
  for (auto& t : transforms_) t.header.stamp = stamp;
  tf_broadcaster_.sendTransform(transforms_);

  // Markers.
  max_tension_seen_ = std::max(max_tension_seen_, c.tension.maxCoeff());
  const double scale = options_.tension_scale > 0.0 ? options_.tension_scale : max_tension_seen_;
  visualization_msgs::Marker& line = marker_msg_.markers[0];
  for (int k = 0; k <= n; ++k) {
    line.points[k].x = c.ends(0, k);
    line.points[k].y = c.ends(1, k);
    line.points[k].z = c.ends(2, k);
    line.colors[k] = tensionColor(c.tension(std::min(k, n - 1)), scale);
  }
  marker_msg_.markers[1].pose.position = line.points[n];
  const double arrow_per_newton = 0.1 * params_.totalLength() / std::max(scale, 1.0);
  const Eigen::Vector3d base_force = c.base_force, load_force = c.load_force;
  for (int i : {2, 3}) {
    const Eigen::Vector3d origin = i == 2 ? Eigen::Vector3d(c.ends.col(0)) : Eigen::Vector3d(c.ends.col(n));
    const Eigen::Vector3d tip = origin + arrow_per_newton * (i == 2 ? base_force : load_force);
    marker_msg_.markers[i].points[0].x = origin.x();
    marker_msg_.markers[i].points[0].y = origin.y();
    marker_msg_.markers[i].points[0].z = origin.z();
    marker_msg_.markers[i].points[1].x = tip.x();
    marker_msg_.markers[i].points[1].y = tip.y();
    marker_msg_.markers[i].points[1].z = tip.z();
  }
  char text[160];
  std::snprintf(text, sizeof(text), "tension: blue 0 N, green %.0f N, red %.0f N  (top %.1f N)", 0.5 * scale, scale,
                c.tension(0));
  marker_msg_.markers[4].text = text;
  marker_msg_.markers[4].pose.position.x = c.ends(0, 0) - 0.3 * params_.totalLength();
  marker_msg_.markers[4].pose.position.z = c.ends(2, 0) + 0.1 * params_.totalLength();
  for (auto& m : marker_msg_.markers) m.header.stamp = stamp;
  marker_pub_.publish(marker_msg_);

  // State and the wrench on the ROV (world frame).
  state_msg_.header.stamp = stamp;
  for (int k = 0; k < n; ++k) state_msg_.tension[k] = c.tension(k);
  state_msg_.top_tension = c.tension(0);
  state_msg_.load_force = vectorMsg(paperToWorld(c.load_force));
  state_msg_.base_force = vectorMsg(paperToWorld(c.base_force));
  state_msg_.kinetic_energy = c.kinetic_energy;
  state_msg_.potential_energy = c.potential_energy;
  state_msg_.elastic_energy = c.elastic_energy;
  state_msg_.dissipated_energy = snapshot_.dissipated_energy;
  state_msg_.sim_time = steps_done_ * sim_->dt();
  state_msg_.step_time = step_seconds;
  state_msg_.real_time_factor = real_time_factor_;
  state_msg_.paused = paused_;
  state_msg_.rejected_inputs = rejected_;
  state_msg_.stale_inputs = stale_;
  state_msg_.diverged_steps = diverged_;
  state_pub_.publish(state_msg_);
  // The ROV feels the coupling's reaction when attached; otherwise the load is the ROV.
  const Eigen::Vector3d on_rov = params_.load.mode == LoadMode::kAttached ? Eigen::Vector3d(-c.coupling_force) : c.load_force;
  wrench_msg_.header.stamp = stamp;
  wrench_msg_.wrench.force = vectorMsg(paperToWorld(on_rov));
  wrench_pub_.publish(wrench_msg_);
}

void CableNode::publishDiagnostics(const ros::Time& stamp) {
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = stamp;
  diagnostic_msgs::DiagnosticStatus status;
  status.name = "cable_dynamics: " + (options_.frame_prefix.empty() ? std::string("cable") : options_.frame_prefix);
  status.hardware_id = names_.paper();
  status.level = diagnostic_msgs::DiagnosticStatus::OK;
  status.message = paused_ ? "paused" : "running";
  if (lag_ > 0.1 || (real_time_factor_ > 0.0 && real_time_factor_ < 0.9 && !paused_)) {
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    status.message = "behind real time";
  }
  if (diverged_ > 0) {
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    status.message = "the simulation diverged and was reset";
  }
  const auto add = [&status](const std::string& key, const std::string& value) {
    diagnostic_msgs::KeyValue kv;
    kv.key = key;
    kv.value = value;
    status.values.push_back(kv);
  };
  add("loop rate [Hz]", std::to_string(loop_rate_));
  add("real-time factor", std::to_string(real_time_factor_));
  add("simulated time [s]", std::to_string(steps_done_ * sim_->dt()));
  add("lag [s]", std::to_string(lag_));
  add("step time [s]", std::to_string(step_seconds_));
  add("rejected inputs", std::to_string(rejected_));
  add("stale inputs", std::to_string(stale_));
  add("diverged steps", std::to_string(diverged_));
  array.status.push_back(status);
  diagnostics_pub_.publish(array);
}

bool CableNode::onReset(cable_msgs::Reset::Request& req, cable_msgs::Reset::Response& res) {
  try {
    if (req.positions.empty()) {
      if (!req.velocities.empty()) throw std::invalid_argument("velocities given without positions");
      sim_->reset();
    } else {
      const Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(req.positions.data(), req.positions.size());
      Eigen::VectorXd qd = Eigen::VectorXd::Zero(q.size());
      if (!req.velocities.empty()) qd = Eigen::Map<const Eigen::VectorXd>(req.velocities.data(), req.velocities.size());
      sim_->setPaperState(q, qd);
    }
  } catch (const std::invalid_argument& e) {
    res.success = false;
    res.message = e.what();
    return true;
  }
  resynchronize();
  alpha_hint_.setZero();
  res.success = true;
  res.message = "reset";
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
  if (paused_ && !req.paused) {
    // Resume where it stopped: the paused interval is not simulated.
    start_stamp_ = ros::Time::now() - ros::Duration(steps_done_ * sim_->dt());
  }
  paused_ = req.paused;
  res.success = true;
  res.message = paused_ ? "paused" : "running";
  return true;
}

}  // namespace cable_dynamics
