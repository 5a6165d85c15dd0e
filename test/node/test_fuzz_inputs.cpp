// Fuzz: 100,000 hostile messages mixed with valid ones on rov_pose, base_pose and current
// (test/fuzz_inputs.test). The test classifies every message by construction with the node's documented
// rules (README.md, "Inputs are guarded") and checks that the node's counters say the same, that every
// message arrived (received_inputs), and that no output carries a non-finite number.
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Core>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include "output_recorder.h"

namespace {

using cable_test::spinFor;
using cable_test::waitFor;

constexpr long kMessages = 100000;
constexpr double kRate = 2000.0;       // messages per second sent [Hz]
constexpr unsigned kInFlight = 500;    // at most this many sent and not yet counted by the node
constexpr double kTimeout = 2.0;       // ros.input_timeout of test/node/fuzz_test.yaml [s]
const std::string kPaperFrame = "fuzz/cable_paper";  // the node's own frame: world rotated half a turn about x

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
const double kDenormal = std::numeric_limits<double>::denorm_min();

enum Expect { kValid, kRejected, kStale };

/// One input topic and what the node's guard remembers of it, as the test models it.
struct Stream {
  ros::Publisher pub;
  ros::Time last_sent;      // strictly increasing stamps for valid messages
  ros::Time last_accepted;  // last valid stamped message (zero: none yet)
  double jump_sign = 1.0;   // successive jumps alternate: never a consistent stream to re-acquire
};

class FuzzInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = std::make_unique<cable_test::OutputRecorder>(nh_, "/fuzz", "cable_dynamics: fuzz/");
    for (int t = 0; t < 3; ++t) {
      const char* topic = t == 0 ? "/fuzz/rov_pose" : t == 1 ? "/fuzz/base_pose" : "/fuzz/current";
      streams_[t].pub = t < 2 ? nh_.advertise<geometry_msgs::PoseStamped>(topic, 1000)
                              : nh_.advertise<geometry_msgs::TwistStamped>(topic, 1000);
    }
    ASSERT_TRUE(waitFor([&] { return out_->allReceived() && out_->marker_count > 10; }, 30.0));
    ASSERT_TRUE(waitFor([&] {
      for (auto& s : streams_) {
        if (s.pub.getNumSubscribers() == 0) return false;
      }
      return true;
    }, 10.0));
    spinFor(1.0);  // the node's tf2 buffer has its own paper frame by now
    const auto& tip = out_->markers.markers.at(0).points.back();
    rov_hold_ = Eigen::Vector3d(tip.x, -tip.y, -tip.z);  // paper to world
  }

  /// A valid stamp for stream `s`: now, strictly after the last one sent.
  ros::Time freshStamp(Stream& s) {
    ros::Time t = ros::Time::now();
    if (t <= s.last_sent) t = s.last_sent + ros::Duration(0, 1000);
    s.last_sent = t;
    return t;
  }

  /// Builds the next message of topic `t` (0 rov, 1 base, 2 current), publishes it and says what the node
  /// must make of it.
  Expect sendOne(int t, std::mt19937& rng) {
    Stream& s = streams_[t];
    std::uniform_real_distribution<double> mm(-1e-3, 1e-3);
    std::uniform_int_distribution<int> pick(0, 99);
    const int kind = pick(rng);
    const bool pose = t < 2;
    const Eigen::Vector3d hold = t == 0 ? rov_hold_ : Eigen::Vector3d::Zero();
    Eigen::Vector3d p = hold + Eigen::Vector3d(mm(rng), mm(rng), mm(rng));
    double q[4] = {0.0, 0.0, 0.0, 1.0};
    Eigen::Vector3d angular = Eigen::Vector3d::Zero();
    if (!pose) p = Eigen::Vector3d(mm(rng), mm(rng), mm(rng)) * 100.0;  // a current of up to 0.1 m/s
    std::string frame = "world";
    ros::Time stamp;
    Expect expect = kValid;
    bool stamped = true;
    const bool recent = !s.last_accepted.isZero() && (ros::Time::now() - s.last_accepted).toSec() < 1.0;

    if (kind < 40) {  // valid, with harmless oddities
      switch (kind % 8) {
        case 1: frame = ""; break;
        case 2: stamped = false; break;
        case 3: q[0] = kDenormal; angular.x() = kDenormal; p.x() += kDenormal; break;
        case 4: q[3] = 0.0; break;                  // a zero quaternion: the orientation is not used
        case 5: q[0] = q[1] = q[2] = q[3] = 7.0; break;  // not normalized: not used either
        case 6: frame = kPaperFrame; p = Eigen::Vector3d(p.x(), -p.y(), -p.z()); break;  // the same point
        default: break;
      }
    } else if (kind < 50) {  // a NaN or an infinity somewhere
      expect = kRejected;
      const double bad = kind % 3 == 0 ? kNan : kind % 3 == 1 ? kInf : -kInf;
      switch (kind % 4) {
        case 0: p.x() = bad; break;
        case 1: p.z() = bad; break;
        case 2: if (pose) q[kind % 4] = bad; else angular.y() = bad; break;
        default: if (pose) q[3] = bad; else angular.z() = bad; break;
      }
    } else if (kind < 58) {  // huge values
      expect = kRejected;
      if (pose) {
        p = kind % 2 ? Eigen::Vector3d(1e308, 1e308, -1e308) : Eigen::Vector3d(0.0, 2e6, 0.0);
      } else {
        p = kind % 2 ? Eigen::Vector3d(1e308, 0.0, 0.0) : Eigen::Vector3d(0.0, 150.0, 0.0);
      }
    } else if (kind < 66) {  // frames: a leading slash, whitespace, unknown
      expect = kRejected;
      const char* const frames[] = {"/world", "a b", "nowhere", "world "};
      frame = frames[kind % 4];
    } else if (kind < 76) {  // stamps too old or too far ahead
      expect = kStale;
      const ros::Time now = ros::Time::now();
      stamp = kind % 3 == 0 ? now - ros::Duration(30.0) : kind % 3 == 1 ? now + ros::Duration(30.0) : ros::Time(1, 0);
    } else if (kind < 86 && recent) {  // a repeated or a backwards stamp
      expect = kRejected;
      stamp = kind % 2 ? s.last_accepted : s.last_accepted - ros::Duration(0.05);
    } else if (kind >= 86 && pose) {  // a 1 km jump
      expect = kRejected;
      p = hold + Eigen::Vector3d(1000.0 * s.jump_sign, 0.0, 0.0);
      s.jump_sign = -s.jump_sign;
    }
    if (expect != kStale && !(expect == kRejected && kind >= 76 && kind < 86)) {
      stamp = stamped ? freshStamp(s) : ros::Time();
    }
    if (expect == kValid && stamped) s.last_accepted = stamp;

    if (pose) {
      geometry_msgs::PoseStamped m;
      m.header.stamp = stamp;
      m.header.frame_id = frame;
      m.pose.position.x = p.x();
      m.pose.position.y = p.y();
      m.pose.position.z = p.z();
      m.pose.orientation.x = q[0];
      m.pose.orientation.y = q[1];
      m.pose.orientation.z = q[2];
      m.pose.orientation.w = q[3];
      s.pub.publish(m);
    } else {
      geometry_msgs::TwistStamped m;
      m.header.stamp = stamp;
      m.header.frame_id = frame;
      m.twist.linear.x = p.x();
      m.twist.linear.y = p.y();
      m.twist.linear.z = p.z();
      m.twist.angular.x = angular.x();
      m.twist.angular.y = angular.y();
      m.twist.angular.z = angular.z();
      s.pub.publish(m);
    }
    return expect;
  }

  ros::NodeHandle nh_;
  std::unique_ptr<cable_test::OutputRecorder> out_;
  Stream streams_[3];
  Eigen::Vector3d rov_hold_;
};

TEST_F(FuzzInputs, HostileMessagesAreCountedExactlyAndNoOutputIsNonFinite) {
  // The first pose of each stream is a valid one, so that later poses are judged against a tracked one.
  std::mt19937 rng(20261201);
  unsigned rejected = 0, stale = 0, sent = 0;
  const unsigned rejected0 = out_->state.rejected_inputs, stale0 = out_->state.stale_inputs;
  const unsigned received0 = out_->state.received_inputs;
  const ros::WallTime start = ros::WallTime::now();
  for (long i = 0; i < kMessages; ++i) {
    const Expect e = sendOne(static_cast<int>(i % 3), rng);
    ++sent;
    rejected += e == kRejected;
    stale += e == kStale;
    if (i % 100 == 99) {
      // Pace to kRate, and never more than kInFlight messages ahead of what the node has counted.
      const ros::WallTime due = start + ros::WallDuration((i + 1) / kRate);
      while (ros::ok() && ros::WallTime::now() < due) {
        ros::spinOnce();
        ros::WallDuration(0.001).sleep();
      }
      ASSERT_TRUE(waitFor([&] { return out_->state.received_inputs - received0 + kInFlight >= sent; }, 10.0))
          << "the node stopped counting inputs at " << out_->state.received_inputs - received0 << " of " << sent;
    }
  }
  ASSERT_TRUE(waitFor([&] { return out_->state.received_inputs - received0 >= sent; }, 20.0));
  spinFor(0.5);
  const double seconds = (ros::WallTime::now() - start).toSec();
  std::printf("fuzz: %u messages in %.1f s; expected %u rejected, %u stale; node: %u received, %u rejected, "
              "%u stale; %ld numbers checked in %ld joint_states, %ld cable_state, %ld markers, %ld wrench, %ld tf, "
              "%ld diagnostics\n", sent, seconds, rejected, stale, out_->state.received_inputs - received0,
              out_->state.rejected_inputs - rejected0, out_->state.stale_inputs - stale0, out_->numbers_checked,
              out_->joint_count, out_->state_count, out_->marker_count, out_->wrench_count, out_->tf_count,
              out_->diagnostics_count);
  // The wall time is printed, not judged (a loaded machine only makes it longer): that the node keeps up is
  // checked above by counts, never more than kInFlight messages sent ahead of what it has counted.
  EXPECT_EQ(out_->state.received_inputs - received0, sent) << "messages were lost on the way";
  EXPECT_EQ(out_->state.rejected_inputs - rejected0, rejected);
  EXPECT_EQ(out_->state.stale_inputs - stale0, stale);
  EXPECT_GT(rejected, 30000u);
  EXPECT_GT(stale, 5000u);
  EXPECT_EQ(out_->non_finite, "") << "a non-finite number was published";
  EXPECT_GT(out_->diagnostics_count, 10);
  EXPECT_GT(out_->tf_count, 1000);
  EXPECT_EQ(out_->state.diverged_steps, 0u);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_fuzz_inputs");
  return RUN_ALL_TESTS();
}
