// The cable's URDF, built with urdfdom, parses back with urdfdom with every link, joint and inertia.
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include "cable_dynamics/urdf/cable_urdf.h"
#include "cable_dynamics/params/config_loader.h"

using namespace cable_dynamics;

TEST(CableUrdf, ParsesBackWithEveryLinkJointAndInertia) {
  const CableParams params = loadConfigString("cable: {links: 4, length: 8.0, diameter: 0.03, mass_per_length: 0.5}");
  CableFrameNames names;
  names.prefix = "umbilical/";
  const std::string xml = cableUrdf(deriveLinkProperties(params), names);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  ASSERT_TRUE(model) << xml;
  EXPECT_EQ(model->getRoot()->name, "umbilical/cable_paper");
  EXPECT_EQ(model->joints_.size(), 12u);  // 3 per link, named as in the JointState
  const LinkProperties props = deriveLinkProperties(params);
  for (int k = 1; k <= 4; ++k) {
    for (const char* direction : {"elevation", "azimuth", "torsion"}) {
      const std::string joint = "umbilical/joint_" + std::to_string(k) + "_" + direction;
      ASSERT_TRUE(model->getJoint(joint)) << joint;
      EXPECT_EQ(model->getJoint(joint)->type, urdf::Joint::CONTINUOUS);
    }
    const urdf::LinkConstSharedPtr link = model->getLink("umbilical/link_" + std::to_string(k));
    ASSERT_TRUE(link && link->inertial && link->visual);
    // urdfdom's exporter writes numbers with 6 significant digits: compare to 1e-5 relative.
    EXPECT_NEAR(link->inertial->mass, props.mass(k - 1), 1e-5 * props.mass(k - 1));
    EXPECT_NEAR(link->inertial->ixx, props.inertia_transverse(k - 1), 1e-5 * props.inertia_transverse(k - 1));
    EXPECT_NEAR(link->inertial->izz, props.inertia_polar(k - 1), 1e-5 * props.inertia_polar(k - 1));
    const auto cylinder = std::dynamic_pointer_cast<urdf::Cylinder>(link->visual->geometry);
    ASSERT_TRUE(cylinder);
    EXPECT_NEAR(cylinder->length, 2.0, 1e-12);
    EXPECT_NEAR(cylinder->radius, 0.015, 1e-12);
  }
  // Joint k+1 sits one link length beyond joint k.
  EXPECT_NEAR(model->getJoint("umbilical/joint_2_azimuth")->parent_to_joint_origin_transform.position.z, 2.0, 1e-12);
}

// Sections and an attachment: each link's radius is its section's, and a point mass on a link joins its
// inertial (total mass, combined centre, transverse inertia about that centre: the parallel-axis sums
// written out here).
TEST(CableUrdf, SectionsAndAttachmentsInTheInertials) {
  const CableParams params = loadConfigString(
      "cable: {links: 4, length: 8.0, diameter: 0.03, mass_per_length: 0.5,\n"
      "        sections: [{length: 4.0, diameter: 0.06, mass_per_length: 2.0}, {}]}\n"
      "attachments: [{arc_length: 5.5, mass: 3.0}]\n");
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(cableUrdf(deriveLinkProperties(params), CableFrameNames()));
  ASSERT_TRUE(model);
  const auto radius = [&](int k) {
    return std::dynamic_pointer_cast<urdf::Cylinder>(model->getLink("link_" + std::to_string(k))->visual->geometry)->radius;
  };
  EXPECT_NEAR(radius(1), 0.03, 1e-12);
  EXPECT_NEAR(radius(3), 0.015, 1e-12);
  // Link 3 (4..6 m): 1 kg of cable centred at 1 m, 3 kg at 1.5 m from its base end.
  const urdf::InertialSharedPtr in = model->getLink("link_3")->inertial;
  const double m = 4.0, centre = (1.0 * 1.0 + 3.0 * 1.5) / m;
  const double own = 1.0 * (4.0 / 12.0 + 0.015 * 0.015 / 4.0);
  const double across = own + 1.0 * (1.0 - centre) * (1.0 - centre) + 3.0 * (1.5 - centre) * (1.5 - centre);
  EXPECT_NEAR(in->mass, m, 1e-5 * m);
  EXPECT_NEAR(in->origin.position.z, centre, 1e-5 * centre);
  EXPECT_NEAR(in->ixx, across, 1e-5 * across);
  EXPECT_NEAR(model->getLink("link_1")->inertial->mass, 4.0, 1e-5);
}
