#include "cable_dynamics/ros/scene_markers.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace cable_dynamics {
namespace {

// Proportions of the shapes, as fractions of the configured sizes: only how they look.
constexpr double kFreeboard = 0.6;              ///< deck above the waterline / hull depth [-]
constexpr double kSternOverhang = 0.06;         ///< sheave aft of the stern / hull length [-]
constexpr double kAFrameHalfWidth = 0.35;       ///< A-frame legs off the sheave / beam [-]
constexpr double kThrusterDiameter = 0.3;       ///< thruster diameter / ROV height [-]
constexpr double kThrusterLength = 0.3;         ///< thruster length / ROV length [-]

std_msgs::ColorRGBA rgb(float r, float g, float b) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = 1.0f;
  return c;
}

void setPoint(geometry_msgs::Point& m, const Eigen::Vector3d& v) {
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
}

void setScale(geometry_msgs::Vector3& m, const Eigen::Vector3d& v) {
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
}

void setOrientation(geometry_msgs::Quaternion& m, const Eigen::Quaterniond& q) {
  m.x = q.x();
  m.y = q.y();
  m.z = q.z();
  m.w = q.w();
}

void start(visualization_msgs::Marker& m, const std::string& frame, const char* ns, int id, int type,
           const std_msgs::ColorRGBA& color) {
  m.header.frame_id = frame;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.color = color;
}

}  // namespace

std_msgs::ColorRGBA tensionColor(double tension, double scale) {
  if (tension < 0.0) return rgb(0.6f, 0.6f, 0.6f);
  const double f = std::clamp(tension / scale, 0.0, 1.0);
  return rgb(static_cast<float>(std::clamp(2.0 * f - 1.0, 0.0, 1.0)), static_cast<float>(1.0 - std::abs(2.0 * f - 1.0)),
             static_cast<float>(std::clamp(1.0 - 2.0 * f, 0.0, 1.0)));
}

void prepareBodyMarkers(const CableParams& params, const BodyShapes& shapes, const std::string& vessel_frame,
                        const std::string& rov_frame, visualization_msgs::Marker* markers) {
  using visualization_msgs::Marker;
  // The vessel (x forward, y to port, z up; its origin on the waterline): the hull floats with 60 % of its
  // depth above the water, the A-frame's feet stand on the deck at the stern and its sheave is the hang-off
  // point, so the cable leaves the sheave (below the deck, e.g. the default hang-off at the origin, the
  // frame reaches down to it like a stern davit).
  const Eigen::Vector3d& top = params.base.hang_off;
  const double length = shapes.vessel_size.x(), beam = shapes.vessel_size.y(), depth = shapes.vessel_size.z();
  const double deck = kFreeboard * depth;                 // [m]
  const double stern = top.x() + kSternOverhang * length;  // [m]
  Marker& hull = markers[0];
  start(hull, vessel_frame, "vessel_hull", 0, Marker::CUBE, rgb(0.45f, 0.5f, 0.58f));
  setPoint(hull.pose.position, {stern + 0.5 * length, 0.0, deck - 0.5 * depth});
  setScale(hull.scale, shapes.vessel_size);
  Marker& house = markers[1];
  start(house, vessel_frame, "vessel_deckhouse", 0, Marker::CUBE, rgb(0.92f, 0.92f, 0.9f));
  setPoint(house.pose.position, {stern + 0.78 * length, 0.0, deck + 0.4 * depth});
  setScale(house.scale, {0.22 * length, 0.7 * beam, 0.8 * depth});
  Marker& aframe = markers[2];
  start(aframe, vessel_frame, "vessel_aframe", 0, Marker::LINE_LIST, rgb(1.0f, 0.45f, 0.1f));
  aframe.scale.x = 0.04 * beam;  // line width [m]
  const double w = kAFrameHalfWidth * beam;
  const Eigen::Vector3d foot_port(stern, top.y() + w, deck), foot_starboard(stern, top.y() - w, deck);
  const Eigen::Vector3d top_port = top + Eigen::Vector3d(0.0, w, 0.0), top_starboard = top - Eigen::Vector3d(0.0, w, 0.0);
  const Eigen::Vector3d segments[6] = {foot_port, top_port, foot_starboard, top_starboard, top_port, top_starboard};
  aframe.points.resize(6);
  for (int i = 0; i < 6; ++i) setPoint(aframe.points[i], segments[i]);

  // The ROV (x forward, y left, z up, about its centre): a yellow body and four horizontal thrusters.
  const Eigen::Vector3d& size = shapes.rov_size;
  Marker& body = markers[3];
  start(body, rov_frame, "rov_body", 0, Marker::CUBE, rgb(1.0f, 0.78f, 0.05f));
  setScale(body.scale, size);
  const double d = kThrusterDiameter * size.z();
  const Eigen::Quaterniond along_x(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY()));  // cylinder z -> x
  for (int i = 0; i < 4; ++i) {
    Marker& thruster = markers[4 + i];
    start(thruster, rov_frame, "rov_thrusters", i, Marker::CYLINDER, rgb(0.15f, 0.15f, 0.15f));
    const double x = (i < 2 ? 0.3 : -0.3) * size.x(), y = (i % 2 == 0 ? 1.0 : -1.0) * (0.5 * size.y() + 0.5 * d);
    setPoint(thruster.pose.position, {x, y, -0.2 * size.z()});
    setOrientation(thruster.pose.orientation, along_x);
    setScale(thruster.scale, {d, d, kThrusterLength * size.x()});
  }
}

void prepareTubeMarkers(const CableParams& params, const std::string& paper_frame,
                        visualization_msgs::Marker* markers) {
  const LinkProperties props = deriveLinkProperties(params);  // each slot's section: its diameter
  for (int k = 0; k < params.links; ++k) {
    visualization_msgs::Marker& m = markers[k];
    start(m, paper_frame, "cable_tube", k, visualization_msgs::Marker::CYLINDER, rgb(0.0f, 0.0f, 1.0f));
    m.scale.x = m.scale.y = 2.0 * props.radius(k);  // the real diameter [m]
    m.scale.z = props.length(k);
  }
}

void fillTubeMarkers(const OutputSource& source, double tension_scale, visualization_msgs::Marker* markers,
                     bool by_utilisation) {
  const ChainOutputs& c = source.snapshot.chain;
  const int n = static_cast<int>(c.tension.size()), first = source.snapshot.first_link;
  for (int k = 0; k < n; ++k) {
    visualization_msgs::Marker& m = markers[k];
    if (k < first) {  // on the drum
      m.action = visualization_msgs::Marker::DELETE;
      continue;
    }
    m.action = visualization_msgs::Marker::ADD;
    // A cylinder's axis is its z: the link frame's (z along the link), centred between the link's ends.
    setPoint(m.pose.position, 0.5 * (c.ends.col(k) + c.ends.col(k + 1)));
    setOrientation(m.pose.orientation, source.snapshot.link_frames[k].orientation);
    m.scale.z = (c.ends.col(k + 1) - c.ends.col(k)).norm();  // the base link's changes with a winch [m]
    m.color = by_utilisation ? utilisationColor(c.limits.utilisation(k)) : tensionColor(c.tension(k), tension_scale);
  }
}

}  // namespace cable_dynamics
