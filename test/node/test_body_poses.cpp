// The ends as bodies over ROS (test/body_poses.test, config test/node/body_test.yaml; issue 14 items 1
// and 2): base_pose with a roll puts the first link's frame at the vessel's hang-off point, moved on its
// arc; base_wrench's moment is r x F in the vessel's frame and base_wrench_world the same wrench in world
// axes; rov_pose turned in yaw and pitch puts the tip at the ROV's attachment point, and rov_wrench is
// the force in the ROV's frame with the moment offset x F about its centre. The expected values are
// computed here from the poses the test sends, not from the node's own quaternions.
#include <cmath>

#include <Eigen/Geometry>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/transform_listener.h>

namespace {

const Eigen::Vector3d kHangOff(4.0, 2.0, 6.0);       // vessel frame [m]
const Eigen::Vector3d kAttachment(-1.0, 0.3, 0.5);   // ROV frame [m]
const std::string kPrefix = "body_test/";

geometry_msgs::WrenchStamped base_wrench, base_wrench_world, rov_wrench, rov_wrench_world;
int wrenches = 0;

Eigen::Vector3d force(const geometry_msgs::WrenchStamped& w) { return {w.wrench.force.x, w.wrench.force.y, w.wrench.force.z}; }
Eigen::Vector3d torque(const geometry_msgs::WrenchStamped& w) { return {w.wrench.torque.x, w.wrench.torque.y, w.wrench.torque.z}; }

geometry_msgs::PoseStamped pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  geometry_msgs::PoseStamped m;
  m.header.stamp = ros::Time::now();
  m.header.frame_id = "world";
  m.pose.position.x = p.x();
  m.pose.position.y = p.y();
  m.pose.position.z = p.z();
  m.pose.orientation.w = q.w();
  m.pose.orientation.x = q.x();
  m.pose.orientation.y = q.y();
  m.pose.orientation.z = q.z();
  return m;
}

/// Publishes `msg` (restamped) every 20 ms for `seconds` of wall time, spinning in between.
void hold(ros::Publisher& pub, geometry_msgs::PoseStamped msg, double seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    msg.header.stamp = ros::Time::now();
    pub.publish(msg);
    ros::WallDuration(0.02).sleep();
    ros::spinOnce();
  }
}

Eigen::Isometry3d lookup(tf2_ros::Buffer& buffer, const std::string& frame) {
  const auto t = buffer.lookupTransform("world", frame, ros::Time(0), ros::Duration(2.0));
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  x.translation() << t.transform.translation.x, t.transform.translation.y, t.transform.translation.z;
  x.linear() = Eigen::Quaterniond(t.transform.rotation.w, t.transform.rotation.x, t.transform.rotation.y,
                                  t.transform.rotation.z).toRotationMatrix();
  return x;
}

}  // namespace

class BodyPosesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    nh = new ros::NodeHandle;
    buffer = new tf2_ros::Buffer;
    listener = new tf2_ros::TransformListener(*buffer);
    const auto keep = [](geometry_msgs::WrenchStamped* into) {
      return boost::function<void(const geometry_msgs::WrenchStamped::ConstPtr&)>(
          [into](const geometry_msgs::WrenchStamped::ConstPtr& m) {
            *into = *m;
            ++wrenches;
          });
    };
    subs = new std::vector<ros::Subscriber>{
        nh->subscribe<geometry_msgs::WrenchStamped>("base_wrench", 10, keep(&base_wrench)),
        nh->subscribe<geometry_msgs::WrenchStamped>("base_wrench_world", 10, keep(&base_wrench_world)),
        nh->subscribe<geometry_msgs::WrenchStamped>("rov_wrench", 10, keep(&rov_wrench)),
        nh->subscribe<geometry_msgs::WrenchStamped>("rov_wrench_world", 10, keep(&rov_wrench_world))};
    base = new ros::Publisher(nh->advertise<geometry_msgs::PoseStamped>("base_pose", 10));
    rov = new ros::Publisher(nh->advertise<geometry_msgs::PoseStamped>("rov_pose", 10));
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::ok() && wrenches < 40 && ros::WallTime::now() < end) {
      ros::WallDuration(0.02).sleep();
      ros::spinOnce();
    }
    ASSERT_GE(wrenches, 40) << "the node published no wrenches within 30 s";
  }
  static ros::NodeHandle* nh;
  static tf2_ros::Buffer* buffer;
  static tf2_ros::TransformListener* listener;
  static std::vector<ros::Subscriber>* subs;
  static ros::Publisher *base, *rov;
};
ros::NodeHandle* BodyPosesTest::nh = nullptr;
tf2_ros::Buffer* BodyPosesTest::buffer = nullptr;
tf2_ros::TransformListener* BodyPosesTest::listener = nullptr;
std::vector<ros::Subscriber>* BodyPosesTest::subs = nullptr;
ros::Publisher* BodyPosesTest::base = nullptr;
ros::Publisher* BodyPosesTest::rov = nullptr;

TEST_F(BodyPosesTest, ARolledVesselMovesTheHangOffPointOnItsArc) {
  // The vessel's origin where it rests (the hang-off point at the world origin), rolled by 0.2 rad.
  const Eigen::Quaterniond roll(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()));
  const Eigen::Vector3d origin = -kHangOff;
  hold(*base, pose(origin, roll), 2.0);
  const Eigen::Vector3d hang_off = origin + roll * kHangOff;  // on the circle about the x axis through the origin
  const Eigen::Isometry3d link = lookup(*buffer, kPrefix + "link_1");
  EXPECT_LT((link.translation() - hang_off).norm(), 1e-6) << "link_1 at " << link.translation().transpose()
                                                            << ", the hang-off point at " << hang_off.transpose();
  EXPECT_NEAR((hang_off - origin).norm(), kHangOff.norm(), 1e-12);
  EXPECT_GT((hang_off - Eigen::Vector3d::Zero()).norm(), 1.0) << "the roll should move the hang-off point";
  const Eigen::Isometry3d vessel = lookup(*buffer, kPrefix + "vessel");
  EXPECT_LT((vessel.translation() - origin).norm(), 1e-6);
  EXPECT_LT((vessel.linear() - roll.toRotationMatrix()).norm(), 1e-6);
  // The wrench on the vessel: in its frame the moment is r x F; in world axes the force turns with R and
  // the moment about the vessel's origin is (R r) x F.
  hold(*base, pose(origin, roll), 0.3);
  const Eigen::Vector3d f_body = force(base_wrench), f_world = force(base_wrench_world);
  ASSERT_GT(f_world.norm(), 10.0);
  EXPECT_LT((torque(base_wrench) - kHangOff.cross(f_body)).norm(), 1e-9 * kHangOff.norm() * f_body.norm());
  EXPECT_LT((roll * f_body - f_world).norm(), 1e-2 * f_world.norm()) << "two messages a cycle apart";
  EXPECT_LT((torque(base_wrench_world) - (roll * kHangOff).cross(f_world)).norm(), 1e-9 * kHangOff.norm() * f_world.norm());
  EXPECT_EQ(base_wrench.header.frame_id, kPrefix + "vessel");
}

TEST_F(BodyPosesTest, ARotatedRovGetsItsWrenchInItsOwnFrame) {
  // The ROV turned 90 degrees in yaw and pitched 0.3 rad, its attachment point 1 m downstream of the tip.
  const Eigen::Quaterniond attitude = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY());
  const Eigen::Vector3d tip(1.0, 0.0, -12.0);  // below the hang-off point, which rests at the origin
  const Eigen::Vector3d centre = tip - attitude * kAttachment;
  hold(*rov, pose(centre, attitude), 3.0);
  const Eigen::Isometry3d load = lookup(*buffer, kPrefix + "cable_load");
  // The tip is held at the attachment point by the PD coupling: within its stretch F / k (5000 N/m).
  EXPECT_LT((load.translation() - tip).norm(), force(rov_wrench_world).norm() / 5000.0 + 1e-3)
      << "tip at " << load.translation().transpose();
  const Eigen::Isometry3d frame = lookup(*buffer, kPrefix + "rov");
  EXPECT_LT((frame.translation() - centre).norm(), 1e-6);
  EXPECT_LT((frame.linear() - attitude.toRotationMatrix()).norm(), 1e-6);
  hold(*rov, pose(centre, attitude), 0.3);
  const Eigen::Vector3d f_body = force(rov_wrench), f_world = force(rov_wrench_world);
  ASSERT_GT(f_world.norm(), 1.0);
  EXPECT_LT((attitude * f_body - f_world).norm(), 1e-2 * f_world.norm()) << "two messages a cycle apart";
  EXPECT_LT((torque(rov_wrench) - kAttachment.cross(f_body)).norm(), 1e-9 * kAttachment.norm() * f_body.norm());
  EXPECT_GT(torque(rov_wrench).norm(), 1.0) << "the attachment off the centre must put a moment on the ROV";
  EXPECT_EQ(rov_wrench.header.frame_id, kPrefix + "rov");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_body_poses");
  return RUN_ALL_TESTS();
}
