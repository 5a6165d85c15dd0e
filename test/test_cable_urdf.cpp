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
