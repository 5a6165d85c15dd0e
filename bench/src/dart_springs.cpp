// DART 6 (Debian's libdart-dev) with joint springs and dampers: the issue-15 anchor. The same BallJoint
// chain as dart_system.cpp, each ball joint with the cable's bending spring and damper on its two
// transverse axes and the torsion spring and damper about the link (DART's joint frame has z along the
// child link), and DART's own time stepping as World::step does it: Skeleton::computeForwardDynamics()
// (the articulated-body algorithm, with the joint springs and dampers implicit in it: DART folds
// h c + h^2 k into each joint's articulated inertia), then integrateVelocities(h) and integratePositions(h)
// (semi-implicit Euler). No fluid: DART has no drag or added mass.
#include <malloc.h>

#include <dart/dynamics/BallJoint.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Inertia.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include "dart_springs.h"

namespace bench {
namespace {

using dart::dynamics::BallJoint;
using dart::dynamics::BodyNode;
using dart::dynamics::Inertia;

class DartSpringSystem : public SteppedSystem {
 public:
  DartSpringSystem(const ChainSpec& spec, const JointSprings& springs) : dt_(spec.dt) {
    // As dart_system.cpp: DART reallocates its dof x dof caches per added body; a heap that keeps its
    // memory while building.
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, 256 << 20);
    skeleton_ = dart::dynamics::Skeleton::create("chain");
    skeleton_->setGravity(Eigen::Vector3d(0.0, 0.0, spec.gravity));
    skeleton_->setTimeStep(spec.dt);
    BodyNode* parent = nullptr;
    for (int k = 0; k < spec.n; ++k) {
      BallJoint::Properties joint;
      joint.mName = "ball" + std::to_string(k);
      joint.mT_ParentBodyToJoint = Eigen::Isometry3d::Identity();
      if (k > 0) joint.mT_ParentBodyToJoint.translation() = Eigen::Vector3d(0.0, 0.0, spec.length[k - 1]);
      const double it = spec.bodyInertiaTransverse(k);
      const Inertia inertia(spec.bodyMass(k), Eigen::Vector3d(0.0, 0.0, spec.bodyCom(k)),
                            Eigen::Vector3d(it, it, spec.bodyInertiaPolar(k)).asDiagonal().toDenseMatrix());
      BodyNode::Properties body(BodyNode::AspectProperties("link" + std::to_string(k), inertia));
      auto pair = skeleton_->createJointAndBodyNodePair<BallJoint>(parent, joint, body);
      parent = pair.second;
      BallJoint* ball = pair.first;
      for (int axis = 0; axis < 3; ++axis) {
        const bool twist = axis == 2;
        ball->setSpringStiffness(axis, twist ? springs.torsion[k] : springs.bending[k]);
        ball->setDampingCoefficient(axis, twist ? springs.torsion_damping[k] : springs.bending_damping[k]);
        ball->setRestPosition(axis, 0.0);  // straight and untwisted
      }
    }
    mallopt(M_MMAP_THRESHOLD, 128 << 10);
    mallopt(M_TRIM_THRESHOLD, 128 << 10);
    mallopt(M_TOP_PAD, 128 << 10);
    malloc_trim(0);
    Eigen::VectorXd q0(skeleton_->getNumDofs());
    for (int k = 0; k < spec.n; ++k) q0.segment<3>(3 * k) = BallJoint::convertToPositions(spec.relativeRotation(k));
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
