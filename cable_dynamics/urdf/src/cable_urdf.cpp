#include "cable_dynamics/urdf/cable_urdf.h"

#include <memory>
#include <stdexcept>

#include <tinyxml.h>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

namespace cable_dynamics {
namespace {

urdf::LinkSharedPtr makeLink(const std::string& name) {
  auto link = std::make_shared<urdf::Link>();
  link->name = name;
  return link;
}

urdf::JointSharedPtr makeJoint(const std::string& name, const std::string& parent, const std::string& child,
                               const urdf::Vector3& axis, double offset_z) {
  auto joint = std::make_shared<urdf::Joint>();
  joint->name = name;
  joint->type = urdf::Joint::CONTINUOUS;
  joint->axis = axis;
  joint->parent_link_name = parent;
  joint->child_link_name = child;
  joint->parent_to_joint_origin_transform.position = urdf::Vector3(0.0, 0.0, offset_z);
  return joint;
}

}  // namespace

std::string cableUrdf(const LinkProperties& p, const CableFrameNames& names) {
  urdf::ModelInterface model;
  model.name_ = names.prefix.empty() ? "cable" : names.prefix.substr(0, names.prefix.size() - 1) + "_cable";
  auto root = makeLink(names.paper());
  model.links_[root->name] = root;
  model.root_link_ = root;
  std::string parent = root->name;
  double offset = 0.0;  // the previous link's length: joint k sits at its far end
  // Per link: the cable's own mass (its section's) and the point attachments it holds, combined into one
  // body: the total mass, its centre and the inertia about it (points add m (s - c)^2 across, none along).
  std::vector<double> point_mass(p.n, 0.0), point_first(p.n, 0.0), point_second(p.n, 0.0);
  for (const LinkAttachment& a : p.attachments) {
    point_mass[a.link] += a.mass;
    point_first[a.link] += a.mass * a.offset;
    point_second[a.link] += a.mass * a.offset * a.offset;
  }
  for (int k = 1; k <= p.n; ++k) {
    const double l = p.length(k - 1), own = p.mass(k - 1), radius = p.radius(k - 1);
    const double m = own + point_mass[k - 1];
    const double centre = m > 0.0 ? (0.5 * l * own + point_first[k - 1]) / m : 0.5 * l;
    // About the base end: I_T + own (l/2)^2 + sum m s^2; shifted to the combined centre.
    const double across = p.inertia_transverse(k - 1) + own * 0.25 * l * l + point_second[k - 1] - m * centre * centre;
    auto z_frame = makeLink(names.afterAzimuth(k)), x_frame = makeLink(names.afterElevation(k));
    auto link = makeLink(names.link(k));
    // Inertia about the CoM, in the link frame (z along the link).
    link->inertial = std::make_shared<urdf::Inertial>();
    link->inertial->mass = m;
    link->inertial->origin.position = urdf::Vector3(0.0, 0.0, centre);
    link->inertial->ixx = link->inertial->iyy = across;
    link->inertial->izz = p.inertia_polar(k - 1);
    link->inertial->ixy = link->inertial->ixz = link->inertial->iyz = 0.0;
    auto cylinder = std::make_shared<urdf::Cylinder>();
    cylinder->radius = radius;
    cylinder->length = l;
    link->visual = std::make_shared<urdf::Visual>();
    link->visual->geometry = cylinder;
    link->visual->origin.position = urdf::Vector3(0.0, 0.0, 0.5 * l);
    link->visual_array.push_back(link->visual);
    for (const auto& l_ptr : {z_frame, x_frame, link}) model.links_[l_ptr->name] = l_ptr;
    const int base_index = 3 * (k - 1);
    auto azimuth = makeJoint(names.joint(base_index + 1), parent, z_frame->name, urdf::Vector3(0, 0, 1), offset);
    auto elevation = makeJoint(names.joint(base_index), z_frame->name, x_frame->name, urdf::Vector3(1, 0, 0), 0.0);
    auto torsion = makeJoint(names.joint(base_index + 2), x_frame->name, link->name, urdf::Vector3(0, 0, 1), 0.0);
    for (const auto& j : {azimuth, elevation, torsion}) model.joints_[j->name] = j;
    parent = link->name;
    offset = l;
  }
  std::unique_ptr<TiXmlDocument> doc(urdf::exportURDF(model));
  if (!doc) throw std::runtime_error("urdfdom could not export the cable URDF");
  TiXmlPrinter printer;
  printer.SetIndent("  ");
  doc->Accept(&printer);
  return printer.CStr();
}

}  // namespace cable_dynamics
