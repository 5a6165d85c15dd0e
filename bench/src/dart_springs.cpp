// DART 6 (Debian's libdart-dev) with joint springs and dampers: the issue-15 anchor. The same BallJoint
// chain as dart_system.cpp, each ball joint with the cable's bending spring and damper on its two
// transverse axes and the torsion spring and damper about the link (DART's joint frame has z along the
// child link), and DART's own time stepping as World::step does it: Skeleton::computeForwardDynamics()
// (the articulated-body algorithm, with the joint springs and dampers implicit in it: DART folds
// h c + h^2 k into each joint's articulated inertia), then integrateVelocities(h) and integratePositions(h)
// (semi-implicit Euler). No fluid: DART has no drag or added mass.
#include <dart/dynamics/BallJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include "dart_chain.h"
#include "dart_springs.h"

namespace bench {
namespace {

using dart::dynamics::BallJoint;

class DartSpringSystem : public SteppedSystem {
 public:
  DartSpringSystem(const ChainSpec& spec, const JointSprings& springs) : dt_(spec.dt) {
    DartChain chain = buildDartChain(spec);
    skeleton_ = chain.skeleton;
    skeleton_->setTimeStep(spec.dt);
    for (int k = 0; k < spec.n; ++k) {
      BallJoint* ball = chain.joints[k];
      for (int axis = 0; axis < 3; ++axis) {
        const bool twist = axis == 2;
        ball->setSpringStiffness(axis, twist ? springs.torsion[k] : springs.bending[k]);
        ball->setDampingCoefficient(axis, twist ? springs.torsion_damping[k] : springs.bending_damping[k]);
        ball->setRestPosition(axis, 0.0);  // straight and untwisted
      }
    }
    const Eigen::VectorXd q0 = initialPositions(spec);
    skeleton_->setPositions(q0);
    skeleton_->setVelocities(Eigen::VectorXd::Zero(skeleton_->getNumDofs()));
  }

  void step() override {
    skeleton_->computeForwardDynamics();
    skeleton_->integrateVelocities(dt_);
    skeleton_->integratePositions(dt_);
  }

  bool finite() override { return skeleton_->getPositions().allFinite() && skeleton_->getVelocities().allFinite(); }

 private:
  double dt_;
  dart::dynamics::SkeletonPtr skeleton_;
};

}  // namespace

std::unique_ptr<SteppedSystem> makeDartSprings(const ChainSpec& spec, const JointSprings& springs) {
  return std::make_unique<DartSpringSystem>(spec, springs);
}

}  // namespace bench
