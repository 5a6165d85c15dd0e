#pragma once
/// \file
/// \brief A publisher that hands out its message as a shared pointer: a subscriber in the same process
///        (the node run as a nodelet in an ROV simulator's manager) receives the pointer itself, with no
///        serialization and no copy on its side; subscribers in other processes get it serialized as
///        before.

#include <string>

#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/node_handle.h>
#include <ros/publisher.h>

namespace cable_dynamics {

/// One topic. The shared message is refilled in place only when nobody else holds it; while a
/// subscriber's queue or callback still holds the last one, the next goes into a fresh message (that
/// cycle allocates), so a subscriber never sees its message change under it.
template <class M>
class SharedPublisher {
 public:
  void advertise(ros::NodeHandle& nh, const std::string& topic, uint32_t queue_size) {
    publisher_ = nh.advertise<M>(topic, queue_size);
    message_ = boost::make_shared<M>();
  }

  /// Copies `filled` (the node's preallocated message, written by index) into the shared message and
  /// publishes it. The copy reuses the shared message's arrays: no allocation once they have the sizes.
  void publish(const M& filled) {
    if (message_.use_count() > 1) {
      message_ = boost::make_shared<M>(filled);
    } else {
      *message_ = filled;
    }
    publisher_.publish(message_);
  }

  /// The message last published (what a subscriber in this process receives).
  boost::shared_ptr<const M> message() const { return message_; }

 private:
  ros::Publisher publisher_;
  boost::shared_ptr<M> message_;
};

}  // namespace cable_dynamics
