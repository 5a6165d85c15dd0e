#include "dart_chain.h"

#include <malloc.h>

#include <string>

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Inertia.hpp>

namespace bench {

using dart::dynamics::BallJoint;
using dart::dynamics::BodyNode;
using dart::dynamics::Inertia;

DartChain buildDartChain(const ChainSpec& spec) {
  // DART 6 reallocates its dof x dof caches (mass matrix and friends) on every body it adds: O(n^2)
  // bytes each, O(n^3) in all. Served from fresh mmap'd pages that takes minutes at n = 1000; from
  // a heap that keeps its memory, about 4x less. Only while building: glibc's defaults again below.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 256 << 20);
  DartChain chain;
  chain.skeleton = dart::dynamics::Skeleton::create("chain");
  chain.skeleton->setGravity(Eigen::Vector3d(0.0, 0.0, spec.gravity));
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
    auto pair = chain.skeleton->createJointAndBodyNodePair<BallJoint>(parent, joint, body);
    chain.joints.push_back(pair.first);
    parent = pair.second;
  }
  chain.last = parent;
  mallopt(M_MMAP_THRESHOLD, 128 << 10);  // glibc's defaults
  mallopt(M_TRIM_THRESHOLD, 128 << 10);
  mallopt(M_TOP_PAD, 128 << 10);
  malloc_trim(0);
  return chain;
}

Eigen::VectorXd initialPositions(const ChainSpec& spec) {
  Eigen::VectorXd q(3 * spec.n);
  for (int k = 0; k < spec.n; ++k) q.segment<3>(3 * k) = BallJoint::convertToPositions(spec.relativeRotation(k));
  return q;
}

}  // namespace bench
