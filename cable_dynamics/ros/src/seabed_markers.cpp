#include "cable_dynamics/ros/seabed_markers.h"

#include <algorithm>

#include "cable_dynamics/dynamics/frames.h"

namespace cable_dynamics {
namespace {

geometry_msgs::Point point(const Eigen::Vector3d& v) {
  geometry_msgs::Point p;
  p.x = v.x();
  p.y = v.y();
  p.z = v.z();
  return p;
}

}  // namespace

visualization_msgs::Marker seabedMarker(const CableParams& params, const std::string& world_frame,
                                        const Eigen::Vector3d& base_position) {
  visualization_msgs::Marker m;
  m.header.frame_id = world_frame;
  m.ns = "seabed";
  m.id = 0;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.color.r = 0.76f;
  m.color.g = 0.65f;
  m.color.b = 0.45f;
  m.color.a = 0.6f;
  const SeabedParams& s = params.seabed;
  if (!s.has_grid) {
    const double reach = 3.0 * std::max(params.totalLength(), 1.0), thickness = 0.02;
    m.type = visualization_msgs::Marker::CUBE;
    m.pose.position = point(base_position + Eigen::Vector3d(0.0, 0.0, -s.depth - 0.5 * thickness));
    m.scale.x = m.scale.y = reach;
    m.scale.z = thickness;
    return m;
  }
  // The grid's cells, two triangles each; the grid is in world axes from the base's rest position.
  m.type = visualization_msgs::Marker::TRIANGLE_LIST;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  const SeabedGrid& g = s.grid;
  auto corner = [&](int i, int j) {
    return point(base_position + Eigen::Vector3d(g.origin.x() + i * g.spacing.x(), g.origin.y() + j * g.spacing.y(), -g.depth(j, i)));
  };
  for (int j = 0; j + 1 < g.depth.rows(); ++j) {
    for (int i = 0; i + 1 < g.depth.cols(); ++i) {
      for (const auto& p : {corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)}) {
        m.points.push_back(p);
      }
    }
  }
  return m;
}

visualization_msgs::Marker contactMarker(const CableParams& params, const std::string& world_frame) {
  visualization_msgs::Marker m;
  m.header.frame_id = world_frame;
  m.ns = "seabed_contact";
  m.id = 1;
  m.type = visualization_msgs::Marker::SPHERE_LIST;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  double diameter = params.diameter;
  for (const SectionParams& s : params.sections) diameter = std::max(diameter, s.diameter);
  m.scale.x = m.scale.y = m.scale.z = std::max(3.0 * diameter, 0.05);  // visible beside the cable's line
  m.color.r = 0.55f;
  m.color.g = 0.27f;
  m.color.b = 0.07f;
  m.color.a = 1.0f;
  m.points.reserve(params.links);
  return m;
}

void fillContactMarker(const SimulationSnapshot& snapshot, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                       visualization_msgs::Marker& marker) {
  marker.header.stamp = stamp;
  marker.points.clear();  // keeps its capacity (reserved for n)
  const Eigen::VectorXd& normal = snapshot.chain.seabed.normal_force;
  for (int k = 0; k < normal.size(); ++k) {
    if (!(normal(k) > 0.0)) continue;
    const Eigen::Vector3d centre = 0.5 * (snapshot.chain.ends.col(k) + snapshot.chain.ends.col(k + 1));
    marker.points.push_back(point(base_position + paperToWorld(centre)));
  }
  // rviz refuses an empty sphere list with a warning: an empty list is deleted instead.
  marker.action = marker.points.empty() ? visualization_msgs::Marker::DELETE : visualization_msgs::Marker::ADD;
}

}  // namespace cable_dynamics
