#pragma once
/// \file
/// \brief The benchmark chain as a DART 6 Skeleton: one BallJoint and one body per link, shared by the
///        plain chain (dart_system.cpp) and the one with joint springs (dart_springs.cpp).

#include <vector>

#include <dart/dynamics/BallJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include "chain_spec.h"

namespace bench {

struct DartChain {
  dart::dynamics::SkeletonPtr skeleton;              ///< a bare Skeleton (no World), gravity set
  std::vector<dart::dynamics::BallJoint*> joints;    ///< joint k: between link k-1 (or the base) and link k
  dart::dynamics::BodyNode* last = nullptr;          ///< the last link's body (the load folded into it)
};

/// Builds `spec`'s chain: joint k at the far end of link k-1 (DART's joint frame has z along the child
/// link), link k's mass, centre of mass and inertia from ChainSpec (the load folded into the last), the
/// skeleton's positions and velocities left at DART's zeros. The positions of `spec`'s initial state:
/// initialPositions().
DartChain buildDartChain(const ChainSpec& spec);

/// DART's generalized positions (three per ball joint, exponential coordinates) of `spec`'s initial state.
Eigen::VectorXd initialPositions(const ChainSpec& spec);

}  // namespace bench
