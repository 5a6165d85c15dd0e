// DART 6 (Debian's libdart-dev): BallJoint chain in a bare Skeleton (no World, no collision), the
// forward dynamics by Skeleton::computeForwardDynamics() (articulated-body algorithm), and a
// hand-written classical RK4 whose position updates use DART's own Skeleton::integratePositions()
// (for a BallJoint: R <- R exp(dt w), the exponential map): every stage starts from the step's
// initial positions, as MuJoCo's RK4 does with mj_integratePos.
//
// DART ships dart::integration::RK4Integrator, but it drives an IntegrableSystem, an interface that
// Skeleton does not implement in DART 6 (World steps with semi-implicit Euler only): there is no DART
// RK4 to call on a Skeleton as it is, so the RK4 is written here around DART's own calls.
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include "chain_spec.h"
#include "dart_chain.h"

namespace bench {
namespace {

using dart::dynamics::BodyNode;
using dart::dynamics::SkeletonPtr;

class DartSystem : public System {
 public:
  explicit DartSystem(const ChainSpec& spec) : spec_(spec) {
    DartChain chain = buildDartChain(spec);
    skeleton_ = chain.skeleton;
    last_ = chain.last;
    const int dof = static_cast<int>(skeleton_->getNumDofs());
    q0_ = initialPositions(spec);
    for (Eigen::VectorXd* v : {&q_, &v_, &qs_, &vs_, &a1_, &a2_, &a3_, &a4_, &vmean_}) v->setZero(dof);
    reset();
  }

  void reset() override {
    q_ = q0_;
    v_.setZero();
  }

  void step() override {
    const double h = spec_.dt;
    accelerations(q_, v_, a1_);
    // Stage 2: positions from q0 along the stage-1 velocity for h/2.
    retract(v_, 0.5 * h, qs_);
    vs_ = v_ + 0.5 * h * a1_;
    accelerations(qs_, vs_, a2_);
    vmean_ = v_ + 2.0 * vs_;  // running sum of v1 + 2 v2 + 2 v3 + v4
    retract(vs_, 0.5 * h, qs_);
    vs_ = v_ + 0.5 * h * a2_;
    accelerations(qs_, vs_, a3_);
    vmean_ += 2.0 * vs_;
    retract(vs_, h, qs_);
    vs_ = v_ + h * a3_;
    accelerations(qs_, vs_, a4_);
    vmean_ += vs_;
    vmean_ /= 6.0;
    retract(vmean_, h, qs_);
    q_ = qs_;
    v_ += (h / 6.0) * (a1_ + 2.0 * a2_ + 2.0 * a3_ + a4_);
  }

  double energy() override {
    skeleton_->setPositions(q_);
    skeleton_->setVelocities(v_);
    // Potential energy summed here: DART 6's BodyNode::computePotentialEnergy() takes the body frame's
    // origin instead of the centre of mass (dartsim/dart#1681, fixed after 6.12).
    double potential = 0.0;
    for (std::size_t i = 0; i < skeleton_->getNumBodyNodes(); ++i) {
      const BodyNode* body = skeleton_->getBodyNode(i);
      potential -= body->getMass() * skeleton_->getGravity().dot(body->getCOM());
    }
    return skeleton_->computeKineticEnergy() + potential;
  }

  Eigen::Vector3d tip() override {
    skeleton_->setPositions(q_);
    return last_->getWorldTransform() * Eigen::Vector3d(0.0, 0.0, spec_.length.back());
  }

 private:
  /// Forward dynamics at (q, v).
  void accelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) {
    skeleton_->setPositions(q);
    skeleton_->setVelocities(v);
    skeleton_->computeForwardDynamics();
    a = skeleton_->getAccelerations();
  }
  /// out = q_ moved along the generalized velocity w for time dt by DART's own position update.
  void retract(const Eigen::VectorXd& w, double dt, Eigen::VectorXd& out) {
    skeleton_->setPositions(q_);
    skeleton_->setVelocities(w);
    skeleton_->integratePositions(dt);
    out = skeleton_->getPositions();
  }

  ChainSpec spec_;
  SkeletonPtr skeleton_;
  BodyNode* last_ = nullptr;
  Eigen::VectorXd q0_, q_, v_, qs_, vs_, a1_, a2_, a3_, a4_, vmean_;
};

}  // namespace

std::unique_ptr<System> makeDart(const ChainSpec& spec) { return std::make_unique<DartSystem>(spec); }

}  // namespace bench
