// The node's messages go out through SharedPublisher (shared_publisher.h): a subscriber in the
// publisher's process (a nodelet manager; here this test) receives the publisher's message object itself,
// not a deserialized copy; a message a subscriber still holds is never refilled; once released, the
// next message reuses it. (Two subscriptions in one process would share one deserialized object even
// without this, so the test compares with the publisher's own message.)
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cable_msgs/CableState.h>

#include "cable_dynamics/ros/shared_publisher.h"

namespace cable_dynamics {

TEST(SharedMessages, ASubscriberInTheProcessGetsThePublishersMessage) {
  ros::NodeHandle nh;
  SharedPublisher<cable_msgs::CableState> publisher;
  publisher.advertise(nh, "probe_state", 10);
  cable_msgs::CableState::ConstPtr received;
  ros::Subscriber sub = nh.subscribe<cable_msgs::CableState>(
      "probe_state", 10, [&received](const cable_msgs::CableState::ConstPtr& m) { received = m; });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while (publisher.message() && sub.getNumPublishers() == 0 && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_EQ(sub.getNumPublishers(), 1u);

  const auto publishAndReceive = [&](double top_tension) {
    cable_msgs::CableState filled;
    filled.tension.assign(50, top_tension);
    filled.top_tension = top_tension;
    received.reset();
    publisher.publish(filled);
    const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(10.0);
    while (!received && ros::WallTime::now() < until) {
      ros::spinOnce();
      ros::WallDuration(0.001).sleep();
    }
    return received;
  };

  cable_msgs::CableState::ConstPtr first = publishAndReceive(1.0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first.get(), publisher.message().get()) << "the subscriber got a copy";
  EXPECT_EQ(first->top_tension, 1.0);
  // Held by the subscriber: the next message is another object, and the held one keeps its values.
  cable_msgs::CableState::ConstPtr second = publishAndReceive(2.0);
  ASSERT_TRUE(second);
  EXPECT_NE(second.get(), first.get());
  EXPECT_EQ(second.get(), publisher.message().get());
  EXPECT_EQ(first->top_tension, 1.0);
  EXPECT_EQ(first->tension[49], 1.0);
  EXPECT_EQ(second->top_tension, 2.0);
  // Released: the next message is refilled in place (its arrays reused, no allocation).
  const void* reused = second.get();
  const double* array = second->tension.data();
  second.reset();
  received.reset();
  cable_msgs::CableState::ConstPtr third = publishAndReceive(3.0);
  ASSERT_TRUE(third);
  EXPECT_EQ(third.get(), reused);
  EXPECT_EQ(third->tension.data(), array);
  EXPECT_EQ(third->top_tension, 3.0);
}

}  // namespace cable_dynamics

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_shared_messages");
  return RUN_ALL_TESTS();
}
