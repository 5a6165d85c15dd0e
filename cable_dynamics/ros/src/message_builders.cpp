#include "cable_dynamics/ros/message_builders.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "cable_dynamics/dynamics/frames.h"

namespace cable_dynamics {
namespace {

/// Half turn about x: the paper frame (z down) in the world frame (z up).
const Eigen::Quaterniond kPaperInWorld(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));

/// A share of steps needing substeps above this makes the diagnostics an ERROR: dt is too large.
constexpr double kRetriedShareError = 0.5;
/// A lag above this makes the diagnostics a WARN [s].
constexpr double kLagWarning = 0.1;

/// The marker array: the cable's line and the load, the force arrows, the scale (kLineMarkers of them), the
/// vessel's and the ROV's shapes (scene_markers.h), then one cylinder per slot (the cable at its diameter).
/// A seabed would take its place after the bodies (scene_markers.h, "Seabed hook").
enum MarkerIndex {
  kCableLine = 0,
  kLoadSphere = 1,
  kBaseArrow = 2,
  kLoadArrow = 3,
  kScaleText = 4,
  kLineMarkers = 5,
  kBodyFirst = kLineMarkers,
  kTubeFirst = kBodyFirst + kSceneMarkerCount
};

void setVector(geometry_msgs::Vector3& m, const Eigen::Vector3d& v) {
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
}

void setPoint(geometry_msgs::Point& m, const Eigen::Vector3d& v) {
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
}

void setPose(geometry_msgs::Transform& t, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  setVector(t.translation, p);
  t.rotation.x = q.x();
  t.rotation.y = q.y();
  t.rotation.z = q.z();
  t.rotation.w = q.w();
}

/// The diagnostics' key-value pairs, in this order (values written by index).
const char* const kDiagnosticKeys[] = {"loop rate [Hz]",    "real-time factor",  "simulated time [s]", "lag [s]",
                                       "dropped time [s]",  "step time [s]",     "received inputs",    "rejected inputs",
                                       "stale inputs",      "diverged steps",    "retried steps",      "retried share",
                                       "energy balance error"};
constexpr int kDiagnosticCount = sizeof(kDiagnosticKeys) / sizeof(kDiagnosticKeys[0]);
/// With a winch, these follow (all numbers but the command, a phrase).
const char* const kWinchKeys[] = {"deployed length [m]", "deployed links", "winch speed [m/s]", "line pull [N]",
                                  "winch command",       "links added",    "links removed"};
constexpr int kWinchCount = sizeof(kWinchKeys) / sizeof(kWinchKeys[0]);
constexpr int kWinchCommandKey = 4;
/// With axial elasticity, these come next.
const char* const kAxialKeys[] = {"slack links", "snaps", "largest tension [N]"};
constexpr int kAxialCount = sizeof(kAxialKeys) / sizeof(kAxialKeys[0]);
/// The limits (cable.limits), always last.
const char* const kLimitKeys[] = {"max utilisation", "min bend radius [m]", "cycles over a limit"};
constexpr int kLimitCount = sizeof(kLimitKeys) / sizeof(kLimitKeys[0]);

/// A radius as published: finite, at most kPublishedStraightRadius [m].
double publishedRadius(double radius) { return std::min(radius, kPublishedStraightRadius); }

/// Moves the `count` entries of `from` starting at `at` to the end of `to` and erases them from `from`;
/// within the capacity of `to`, no allocation (moved strings keep their buffers).
template <class T>
void moveOut(std::vector<T>& from, std::size_t at, std::size_t count, std::vector<T>& to) {
  to.insert(to.end(), std::make_move_iterator(from.begin() + at), std::make_move_iterator(from.begin() + at + count));
  from.erase(from.begin() + at, from.begin() + at + count);
}

/// Moves the last `count` entries of `from` into `to` at `at`, in their order, and drops them from `from`.
template <class T>
void moveIn(std::vector<T>& from, std::size_t count, std::vector<T>& to, std::size_t at) {
  to.insert(to.begin() + at, std::make_move_iterator(from.end() - count), std::make_move_iterator(from.end()));
  from.resize(from.size() - count);
}

void format(std::string& out, const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), pattern, value);
  out = text;
}

}  // namespace

void prepareOutputs(const CableParams& params, const CableFrameNames& names, const std::string& world_frame,
                    CableOutputs& out, const BodyShapes& shapes) {
  const int n = params.links, dof = 3 * n;
  out.joints.name.resize(dof);
  for (int i = 0; i < dof; ++i) out.joints.name[i] = names.joint(i);
  out.joints.position.assign(dof, 0.0);
  out.joints.velocity.assign(dof, 0.0);
  out.joints.effort.assign(dof, 0.0);

  // TF: world -> paper frame, then every link frame, the URDF's intermediate frames, and the load.
  out.transforms.resize(2 + 3 * n);
  out.transforms[0].header.frame_id = world_frame;
  out.transforms[0].child_frame_id = names.paper();
  for (int k = 0; k < n; ++k) {
    out.transforms[1 + 3 * k].child_frame_id = names.link(k + 1);
    out.transforms[2 + 3 * k].child_frame_id = names.afterAzimuth(k + 1);
    out.transforms[3 + 3 * k].child_frame_id = names.afterElevation(k + 1);
  }
  out.transforms.back().child_frame_id = names.load();
  for (std::size_t i = 1; i < out.transforms.size(); ++i) out.transforms[i].header.frame_id = names.paper();

  // Markers: the cable coloured by tension, the load, force arrows at both ends, the colour scale; the
  // bodies; the cable at its diameter.
  out.markers.markers.resize(kTubeFirst + n);
  const char* const kNamespaces[kLineMarkers] = {"cable", "load", "base_force", "load_force", "tension_scale"};
  const int kTypes[kLineMarkers] = {visualization_msgs::Marker::LINE_STRIP, visualization_msgs::Marker::SPHERE,
                                    visualization_msgs::Marker::ARROW, visualization_msgs::Marker::ARROW,
                                    visualization_msgs::Marker::TEXT_VIEW_FACING};
  for (int i = 0; i < kLineMarkers; ++i) {
    visualization_msgs::Marker& m = out.markers.markers[i];
    m.header.frame_id = names.paper();
    m.ns = kNamespaces[i];
    m.id = 0;
    m.type = kTypes[i];
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.color.a = 1.0;
  }
  const double length = params.totalLength();
  // The overview's line: a few pixels wide at a whole-cable view (0.4 % of the length: ~3 px for a 50 m
  // cable across 1000 px), at least 4 diameters; see-through, so that the tube at its real diameter shows
  // inside it from close by.
  const double width = std::max(4.0 * params.diameter, 0.004 * length);  // [m]
  visualization_msgs::Marker& line = out.markers.markers[kCableLine];
  line.scale.x = width;
  line.points.resize(n + 1);
  line.colors.resize(n + 1);
  visualization_msgs::Marker& load = out.markers.markers[kLoadSphere];
  load.scale.x = load.scale.y = load.scale.z = std::max(0.5, 0.03 * length);
  load.color.r = 1.0;
  load.color.g = 0.8f;
  for (int i : {kBaseArrow, kLoadArrow}) {
    visualization_msgs::Marker& arrow = out.markers.markers[i];
    arrow.points.resize(2);
    arrow.scale.x = width;        // shaft diameter
    arrow.scale.y = 2.0 * width;  // head diameter
    arrow.scale.z = 3.0 * width;  // head length
    arrow.color.r = 1.0;
    arrow.color.b = 1.0;
  }
  visualization_msgs::Marker& text = out.markers.markers[kScaleText];
  text.scale.z = std::max(0.3, 0.012 * length);  // a legend, not a headline: ~1/4 of the view's width
  text.color.r = text.color.g = text.color.b = 1.0;
  text.text.reserve(160);
  prepareBodyMarkers(params, shapes, names.vessel(), names.rov(), &out.markers.markers[kBodyFirst]);
  prepareTubeMarkers(params, names.paper(), &out.markers.markers[kTubeFirst]);

  out.state.tension.assign(n, 0.0);
  out.state.seabed_force.assign(params.seabed.enabled ? n : 0, 0.0);
  out.state.strain.assign(params.stretches() ? n : 0, 0.0);
  out.state.bend_radius.assign(n, kPublishedStraightRadius);
  out.state.utilisation.assign(n, 0.0);
  out.state.min_bend_radius = kPublishedStraightRadius;
  out.state.axial = params.stretches();
  out.state.deployed_links = static_cast<uint32_t>(n);
  out.state.header.frame_id = world_frame;
  out.wrench.header.frame_id = names.rov();           // about the ROV's origin, in its axes
  out.wrench_world.header.frame_id = names.load();    // at the load, axes parallel to the world frame's
  out.base_wrench.header.frame_id = names.vessel();   // about the vessel's origin, in its axes
  out.base_wrench_world.header.frame_id = world_frame;  // about the vessel's origin, in world axes
  out.body_transforms.resize(2);
  for (auto& t : out.body_transforms) t.header.frame_id = world_frame;
  out.body_transforms[0].child_frame_id = names.vessel();
  out.body_transforms[1].child_frame_id = names.rov();

  out.diagnostics.status.resize(1);
  diagnostic_msgs::DiagnosticStatus& status = out.diagnostics.status[0];
  status.name = "cable_dynamics: " + (names.prefix.empty() ? std::string("cable") : names.prefix);
  status.hardware_id = names.paper();
  const bool winch = params.winch.enabled, axial = params.stretches();
  status.values.resize(kDiagnosticCount + (winch ? kWinchCount : 0) + (axial ? kAxialCount : 0) + kLimitCount);
  for (int i = 0; i < kDiagnosticCount; ++i) {
    status.values[i].key = kDiagnosticKeys[i];
    status.values[i].value.reserve(32);
  }
  for (int i = 0; winch && i < kWinchCount; ++i) {
    status.values[kDiagnosticCount + i].key = kWinchKeys[i];
    status.values[kDiagnosticCount + i].value.reserve(64);
  }
  for (int i = 0, first = static_cast<int>(status.values.size()) - kLimitCount - kAxialCount; axial && i < kAxialCount; ++i) {
    status.values[first + i].key = kAxialKeys[i];
    status.values[first + i].value.reserve(32);
  }
  for (int i = 0, first = static_cast<int>(status.values.size()) - kLimitCount; i < kLimitCount; ++i) {
    status.values[first + i].key = kLimitKeys[i];
    status.values[first + i].value.reserve(32);
  }
  status.message.reserve(256);  // the limits' message names the limits and links

  // Everything is sized for every slot; the drum's entries are moved aside.
  out.slots = n;
  out.first_link = 0;
  out.stowed_joint_names.clear();
  out.stowed_joint_names.reserve(dof);
  out.stowed_transforms.clear();
  out.stowed_transforms.reserve(dof);
  shapeOutputs(params.drumSlots(), out);
}

void shapeOutputs(int first_link, CableOutputs& out) {
  const int n = out.slots;
  first_link = std::clamp(first_link, 0, n - 1);
  if (first_link == out.first_link) return;
  while (out.first_link < first_link) {  // hauled in: slot first_link goes onto the drum
    moveOut(out.joints.name, 0, 3, out.stowed_joint_names);
    moveOut(out.transforms, 1, 3, out.stowed_transforms);
    ++out.first_link;
  }
  while (out.first_link > first_link) {  // paid out: slot first_link - 1 comes off the drum
    moveIn(out.stowed_joint_names, 3, out.joints.name, 0);
    moveIn(out.stowed_transforms, 3, out.transforms, 1);
    --out.first_link;
  }
  const std::size_t deployed = static_cast<std::size_t>(n - first_link);
  out.joints.position.resize(3 * deployed);  // within the capacity of 3n: no allocation
  out.joints.velocity.resize(3 * deployed);
  out.joints.effort.resize(3 * deployed);
  visualization_msgs::Marker& line = out.markers.markers[kCableLine];
  line.points.resize(deployed + 1);
  line.colors.resize(deployed + 1);
}

WinchStatus winchStatus(const OutputSource& source) {
  WinchStatus w;
  const SimulationSnapshot& s = source.snapshot;
  w.present = source.winch.present;
  w.deployed_length = s.deployed_length;
  w.speed = s.winch_speed;
  w.line_pull = s.line_pull;
  w.deployed_links = static_cast<unsigned>(s.chain.tension.size() - s.first_link);
  w.targeting = source.winch.targeting;
  w.commanded_speed = source.winch.commanded_speed;
  w.target_length = source.winch.target_length;
  w.links_added = static_cast<unsigned>(source.winch.links_added);
  w.links_removed = static_cast<unsigned>(source.winch.links_removed);
  return w;
}

void fillJointState(const OutputSource& source, const ros::Time& stamp, sensor_msgs::JointState& msg) {
  const SimulationSnapshot& s = source.snapshot;
  const int from = 3 * s.first_link;  // the deployed links' coordinates
  for (int i = from; i < s.q.size(); ++i) {
    msg.position[i - from] = s.q(i);
    msg.velocity[i - from] = s.qd(i);
    msg.effort[i - from] = -source.spring_force(i);
  }
  msg.header.stamp = stamp;
}

void fillTransforms(const OutputSource& source, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                    std::vector<geometry_msgs::TransformStamped>& transforms) {
  const PoseVector& links = source.snapshot.link_frames;
  const int n = static_cast<int>(links.size()), first = source.snapshot.first_link;
  setPose(transforms[0].transform, base_position, kPaperInWorld);
  for (int k = first; k < n; ++k) {  // a link on the drum has no frame
    const int i = 3 * (k - first);
    const Pose &link = links[k], &azimuth = source.snapshot.after_azimuth[k], &elevation = source.snapshot.after_elevation[k];
    setPose(transforms[1 + i].transform, link.position, link.orientation);
    setPose(transforms[2 + i].transform, azimuth.position, azimuth.orientation);
    setPose(transforms[3 + i].transform, elevation.position, elevation.orientation);
  }
  // The load frame is aligned with the world frame (only translated), so the wrench reads in world axes.
  setPose(transforms.back().transform, source.snapshot.chain.ends.col(n), kPaperInWorld.conjugate());
  for (auto& t : transforms) t.header.stamp = stamp;
}

namespace {
/// The overview line's opacity: the real-diameter tube stays visible inside it.
constexpr float kOverviewLineAlpha = 0.45f;
}  // namespace

void fillMarkers(const OutputSource& source, double total_length, double tension_scale, const ros::Time& stamp,
                 visualization_msgs::MarkerArray& msg, MarkerColour colour_by) {
  const ChainOutputs& c = source.snapshot.chain;
  const int n = static_cast<int>(c.tension.size()), first = source.snapshot.first_link;
  const bool by_utilisation = colour_by == MarkerColour::kUtilisation;
  // The line runs over the deployed links only (one marker, replaced each cycle: a link hauled in leaves
  // nothing behind in rviz).
  visualization_msgs::Marker& line = msg.markers[kCableLine];
  for (int k = first; k <= n; ++k) {
    const int link = std::min(k, n - 1);
    setPoint(line.points[k - first], c.ends.col(k));
    line.colors[k - first] = by_utilisation ? utilisationColor(c.limits.utilisation(link))
                                            : tensionColor(c.tension(link), tension_scale);
    line.colors[k - first].a = kOverviewLineAlpha;
  }
  msg.markers[kLoadSphere].pose.position = line.points[n - first];
  const double arrow_per_newton = 0.1 * total_length / std::max(tension_scale, 1.0);  // [m/N]
  const Eigen::Vector3d base = c.ends.col(first), tip = c.ends.col(n);
  setPoint(msg.markers[kBaseArrow].points[0], base);
  setPoint(msg.markers[kBaseArrow].points[1], base + arrow_per_newton * c.base_force);
  setPoint(msg.markers[kLoadArrow].points[0], tip);
  setPoint(msg.markers[kLoadArrow].points[1], tip + arrow_per_newton * c.load_force);
  char text[160];
  if (by_utilisation) {
    std::snprintf(text, sizeof(text), "utilisation: blue 0, green 0.5, red 1 = a limit  (largest %.2f, link %d)",
                  c.limits.max_utilisation, c.limits.max_utilisation_link + 1);
  } else {
    std::snprintf(text, sizeof(text), "tension: blue 0 N, green %.0f N, red %.0f N  (top %.1f N)", 0.5 * tension_scale,
                  tension_scale, source.snapshot.line_pull);
  }
  visualization_msgs::Marker& label = msg.markers[kScaleText];
  label.text = text;
  label.pose.position.x = c.ends(0, first) - 0.3 * total_length;
  label.pose.position.z = c.ends(2, first) + 0.1 * total_length;
  fillTubeMarkers(source, tension_scale, &msg.markers[kTubeFirst], colour_by == MarkerColour::kUtilisation);
  for (auto& m : msg.markers) m.header.stamp = stamp;
}

void fillCableState(const OutputSource& source, const NodeStatus& status, const ros::Time& stamp,
                    cable_msgs::CableState& msg) {
  const SimulationSnapshot& s = source.snapshot;
  const ChainOutputs& c = s.chain;
  msg.header.stamp = stamp;
  for (int k = 0; k < c.tension.size(); ++k) msg.tension[k] = c.tension(k);  // per slot: 0 on the drum
  msg.top_tension = s.line_pull;
  msg.deployed_length = s.deployed_length;
  msg.line_pull = s.line_pull;
  msg.winch_speed = s.winch_speed;
  msg.first_link = static_cast<uint32_t>(s.first_link);
  msg.deployed_links = static_cast<uint32_t>(c.tension.size() - s.first_link);
  msg.links_added = static_cast<uint32_t>(source.winch.links_added);
  msg.links_removed = static_cast<uint32_t>(source.winch.links_removed);
  setVector(msg.load_force, paperToWorld(c.load_force));
  setVector(msg.base_force, paperToWorld(c.base_force));
  msg.kinetic_energy = c.kinetic_energy;
  msg.potential_energy = c.potential_energy;
  msg.elastic_energy = c.elastic_energy;
  msg.dissipated_energy = s.dissipated_energy;
  msg.sim_time = s.time;
  msg.step_time = status.step_time;
  msg.real_time_factor = status.real_time_factor;
  msg.lag = status.lag;
  msg.paused = status.paused;
  msg.received_inputs = status.received;
  msg.rejected_inputs = status.rejected;
  msg.stale_inputs = status.stale;
  msg.refused_commands = status.refused_commands;
  msg.diverged_steps = status.diverged;
  msg.retried_steps = status.retried;
  const SeabedReport& bed = c.seabed;
  msg.seabed = !msg.seabed_force.empty();
  msg.grounded_length = bed.grounded_length;
  msg.touchdown_arc_length = bed.touching ? bed.touchdown_arc_length : -1.0;
  const Eigen::Vector3d touchdown = paperToWorld(bed.touchdown);
  msg.touchdown.x = touchdown.x();
  msg.touchdown.y = touchdown.y();
  msg.touchdown.z = touchdown.z();
  msg.max_penetration = bed.max_penetration;
  msg.contact_energy = c.contact_energy;
  for (std::size_t k = 0; k < msg.seabed_force.size() && k < static_cast<std::size_t>(bed.normal_force.size()); ++k) {
    msg.seabed_force[k] = bed.normal_force(k);
  }
  for (std::size_t k = 0; k < msg.strain.size() && k < static_cast<std::size_t>(c.strain.size()); ++k) {
    msg.strain[k] = c.strain(k);
  }
  msg.slack_links = static_cast<uint32_t>(c.slack_links);
  msg.max_tension = s.largest_tension;
  msg.snaps = static_cast<uint32_t>(s.snaps);
  const LimitReport& limits = c.limits;
  for (std::size_t k = 0; k < msg.bend_radius.size() && k < static_cast<std::size_t>(limits.bend_radius.size()); ++k) {
    msg.bend_radius[k] = publishedRadius(limits.bend_radius(k));
    msg.utilisation[k] = limits.utilisation(k);
  }
  msg.max_utilisation = limits.max_utilisation;
  msg.min_bend_radius = publishedRadius(limits.min_bend_radius);
}

void updateLimitStatus(const SimulationSnapshot& snapshot, LimitStatus& status) {
  const LimitReport& r = snapshot.chain.limits;
  status.tension = r.tension_exceeded;
  status.bend = r.bend_exceeded;
  status.clearance = r.clearance_exceeded;
  status.tension_link = r.max_tension_utilisation_link;
  status.bend_link = r.max_bend_utilisation_link;
  status.clearance_link = r.seabed_clearance_link;
  status.tension_utilisation = r.max_tension_utilisation;
  status.bend_utilisation = r.max_bend_utilisation;
  status.max_utilisation = r.max_utilisation;
  status.min_bend_radius = publishedRadius(r.min_bend_radius);
  status.seabed_clearance = publishedRadius(r.seabed_clearance);
  if (status.exceeded()) ++status.cycles_in_excess;
}

void fillWrenches(const OutputSource& source, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                  CableOutputs& out) {
  const SimulationSnapshot& s = source.snapshot;
  const auto set = [&stamp](geometry_msgs::WrenchStamped& msg, const Eigen::Vector3d& force, const Eigen::Vector3d& moment) {
    msg.header.stamp = stamp;
    setVector(msg.wrench.force, force);
    setVector(msg.wrench.torque, moment);
  };
  set(out.wrench, s.rov.force_body, s.rov.moment_body);
  // The snapshot is in the paper frame: the world-axes messages and the bodies' frames turn it here.
  set(out.wrench_world, paperToWorld(s.rov.force), Eigen::Vector3d::Zero());
  set(out.base_wrench, s.vessel.force_body, s.vessel.moment_body);
  set(out.base_wrench_world, paperToWorld(s.vessel.force), paperToWorld(s.vessel.moment));
  setPose(out.body_transforms[0].transform, base_position + paperToWorld(s.vessel_origin),
          paperToWorldAttitude(s.vessel_attitude));
  setPose(out.body_transforms[1].transform, base_position + paperToWorld(s.rov_origin),
          paperToWorldAttitude(s.rov_attitude));
  for (auto& t : out.body_transforms) t.header.stamp = stamp;
}

/// The energy balance's error beyond which the diagnostics warn [-]: cable_sim's exit-5 bound for a rise.
constexpr double kEnergyErrorWarning = 1e-2;

unsigned char diagnosticLevel(const NodeStatus& s, std::string& message) {
  using diagnostic_msgs::DiagnosticStatus;
  if (s.diverged_recently) {
    message = "the simulation diverged and was recovered (initial shape; time and inputs carry on)";
    return DiagnosticStatus::ERROR;
  }
  if (s.retried_share > kRetriedShareError) {
    message = "most steps need substeps: simulation.dt is too large for this cable";
    return DiagnosticStatus::ERROR;
  }
  if (s.dropped_recently) {
    message = "cannot keep up with the clock: simulated time dropped (lag above ros.max_lag)";
    return DiagnosticStatus::ERROR;
  }
  if (s.limits.exceeded()) {
    // Names each limit exceeded and its link (link K = slot K - 1, as the TF frames link_K); no allocation
    // beyond the message's reserved capacity.
    const LimitStatus& l = s.limits;
    char text[256];
    int used = std::snprintf(text, sizeof(text), "limit exceeded (%u cycles so far):", l.cycles_in_excess);
    const auto add = [&](const char* format, double a, double b) {
      if (used < static_cast<int>(sizeof(text))) used += std::snprintf(text + used, sizeof(text) - used, format, a, b);
    };
    if (l.tension) add(" tension on link %.0f (utilisation %.3g);", l.tension_link + 1.0, l.tension_utilisation);
    if (l.bend) add(" bend on link %.0f (utilisation %.3g);", l.bend_link + 1.0, l.bend_utilisation);
    if (l.clearance) add(" seabed clearance at link %.0f (%.3g m);", l.clearance_link + 1.0, l.seabed_clearance);
    message = text;
    return DiagnosticStatus::WARN;
  }
  if (s.energy_error > kEnergyErrorWarning) {
    message = "the energy balance rose or drifted beyond 1 % of its scale: simulation.dt is too large for this cable";
    return DiagnosticStatus::WARN;
  }
  if (!s.paused && (s.lag > kLagWarning || (s.real_time_factor > 0.0 && s.real_time_factor < 0.9))) {
    message = "behind real time";
    return DiagnosticStatus::WARN;
  }
  if (s.diverged > 0) {
    message = "running; the simulation diverged earlier and was recovered";
    return DiagnosticStatus::WARN;
  }
  message = s.paused ? "paused" : "running";
  return DiagnosticStatus::OK;
}

void fillDiagnostics(const NodeStatus& s, const ros::Time& stamp, diagnostic_msgs::DiagnosticArray& msg) {
  msg.header.stamp = stamp;
  diagnostic_msgs::DiagnosticStatus& status = msg.status[0];
  status.level = diagnosticLevel(s, status.message);
  const double values[kDiagnosticCount] = {s.loop_rate,        s.real_time_factor, s.sim_time,   s.lag,
                                           s.dropped_time,     s.step_time,        double(s.received),
                                           double(s.rejected), double(s.stale),    double(s.diverged),
                                           double(s.retried),  s.retried_share,    s.energy_error};
  for (int i = 0; i < kDiagnosticCount; ++i) format(status.values[i].value, i >= 6 && i <= 10 ? "%.0f" : "%.6g", values[i]);
  const int last = static_cast<int>(status.values.size()) - kLimitCount;  // the axial keys end before the limits'
  const double limit_values[kLimitCount] = {s.limits.max_utilisation, s.limits.min_bend_radius,
                                            double(s.limits.cycles_in_excess)};
  for (int i = 0; i < kLimitCount; ++i) format(status.values[last + i].value, i == 2 ? "%.0f" : "%.6g", limit_values[i]);
  if (last >= kDiagnosticCount + kAxialCount && status.values[last - kAxialCount].key == kAxialKeys[0]) {
    const double axial_values[kAxialCount] = {double(s.slack_links), double(s.snaps), s.largest_tension};
    for (int i = 0; i < kAxialCount; ++i) format(status.values[last - kAxialCount + i].value, i < 2 ? "%.0f" : "%.6g", axial_values[i]);
  }
  if (!s.winch.present) return;  // no winch
  const WinchStatus& w = s.winch;
  const double winch_values[kWinchCount] = {w.deployed_length, double(w.deployed_links), w.speed, w.line_pull, 0.0,
                                            double(w.links_added), double(w.links_removed)};
  for (int i = 0; i < kWinchCount; ++i) {
    if (i == kWinchCommandKey) continue;
    format(status.values[kDiagnosticCount + i].value, i == 1 || i >= 5 ? "%.0f" : "%.6g", winch_values[i]);
  }
  char command[64];
  if (w.targeting) {
    std::snprintf(command, sizeof(command), "to length %.6g m", w.target_length);
  } else if (w.commanded_speed > 0.0) {
    std::snprintf(command, sizeof(command), "pay out at %.6g m/s", w.commanded_speed);
  } else if (w.commanded_speed < 0.0) {
    std::snprintf(command, sizeof(command), "haul in at %.6g m/s", -w.commanded_speed);
  } else {
    std::snprintf(command, sizeof(command), "stop (speed 0)");
  }
  status.values[kDiagnosticCount + kWinchCommandKey].value = command;  // within its reserved capacity
}

}  // namespace cable_dynamics
