#include "cable_dynamics/dynamics/chain_deployment.h"

#include <algorithm>

namespace cable_dynamics {

void ChainDeployment::dropHold(int i) {
  for (int j = i; j + 1 < hold_count_; ++j) holds_[j] = holds_[j + 1];
  --hold_count_;
}

void ChainDeployment::holdJoint(int joint, const Eigen::Vector3d& torque, double damping, double start,
                                double deployed, double span) {
  int i = 0;
  while (i < hold_count_ && holds_[i].joint != joint) ++i;
  if (i == hold_count_) {
    if (hold_count_ == kMaxJointHolds) dropHold(0);
    i = hold_count_++;
  }
  holds_[i] = JointHold{joint, torque, start, deployed, span, damping, 1.0, torque};
}

void ChainDeployment::setHoldState(double t, double deployed) {
  for (int i = 0; i < hold_count_; ++i) {
    JointHold& h = holds_[i];
    const double paid = (deployed - h.deployed) / h.span;
    const double waited = kJointHoldLinks * (t - h.start) / kJointHoldLongest;
    h.fraction = jointHoldLeft(std::max(paid, waited));
    h.now = h.fraction * h.initial;
  }
}

void ChainDeployment::dropReleasedHolds() {
  for (int i = hold_count_ - 1; i >= 0; --i) {
    if (holds_[i].fraction <= 0.0) dropHold(i);
  }
}

}  // namespace cable_dynamics
