// Orocos KDL 1.5 (Debian's liborocos-kdl-dev): KDL has no ball joint, so each link hangs on three
// revolute joints about the parent frame's x, y and the link's own z axis (X-Y-Z Euler angles of the
// link relative to its parent; two massless intermediate segments per link; singular, gimbal lock,
// only where the middle angle reaches +-90 deg, far from this benchmark's bends). Forward dynamics
// by KDL::ChainFdSolver_RNE (joint-space mass matrix by composite rigid bodies, bias by recursive
// Newton-Euler, then an LDL^T solve: O(n^3) in the chain length), inside a hand-written classical
// RK4. The joint angles are plain Euclidean coordinates, so that RK4 needs no approximation.
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainfdsolver_recursive_newton_euler.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>
#include <kdl/segment.hpp>

#include "chain_spec.h"

namespace bench {
namespace {

class KdlSystem : public System {
 public:
  explicit KdlSystem(const ChainSpec& spec) : spec_(spec) {
    const KDL::RigidBodyInertia none = KDL::RigidBodyInertia::Zero();
    for (int k = 0; k < spec.n; ++k) {
      const double l = spec.length[k], it = spec.bodyInertiaTransverse(k);
      chain_.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotX), KDL::Frame::Identity(), none));
      chain_.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotY), KDL::Frame::Identity(), none));
      // The body segment's tip frame is the link's far end (the next joint); KDL expresses a segment's
      // inertia in its tip frame, so the centre of mass sits at (0, 0, com - l) there.
      const KDL::RigidBodyInertia inertia(spec.bodyMass(k), KDL::Vector(0, 0, spec.bodyCom(k) - l),
                                          KDL::RotationalInertia(it, it, spec.bodyInertiaPolar(k), 0, 0, 0));
      chain_.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ), KDL::Frame(KDL::Vector(0, 0, l)), inertia));
    }
    const KDL::Vector gravity(0, 0, spec.gravity);
    solver_ = std::make_unique<KDL::ChainFdSolver_RNE>(chain_, gravity);
    params_ = std::make_unique<KDL::ChainDynParam>(chain_, gravity);
    const int dof = static_cast<int>(chain_.getNrOfJoints());
    q0_.resize(dof);
    for (int k = 0; k < spec.n; ++k) {
      // R = Rx(a) Ry(b) Rz(c): R02 = sin b, R12 = -sin a cos b, R22 = cos a cos b, R01 = -cos b sin c, R00 = cos b cos c.
      const Eigen::Matrix3d r = spec.relativeRotation(k);
      q0_(3 * k) = std::atan2(-r(1, 2), r(2, 2));
      q0_(3 * k + 1) = std::asin(std::max(-1.0, std::min(1.0, r(0, 2))));
      q0_(3 * k + 2) = std::atan2(-r(0, 1), r(0, 0));
    }
    for (KDL::JntArray* a : {&q_, &v_, &qs_, &vs_, &a1_, &a2_, &a3_, &a4_, &zero_}) a->resize(dof);
    external_.assign(chain_.getNrOfSegments(), KDL::Wrench::Zero());
    reset();
  }

  void reset() override {
    q_ = q0_;
    SetToZero(v_);
  }

  void step() override {
    const double h = spec_.dt;
    const Eigen::VectorXd &q = q_.data, &v = v_.data;
    accelerations(q_, v_, a1_);
    qs_.data = q + 0.5 * h * v;
    vs_.data = v + 0.5 * h * a1_.data;
    Eigen::VectorXd& vsum = sum_;
    vsum = v;
    accelerations(qs_, vs_, a2_);
    vsum += 2.0 * vs_.data;
    qs_.data = q + 0.5 * h * vs_.data;
    vs_.data = v + 0.5 * h * a2_.data;
    accelerations(qs_, vs_, a3_);
    vsum += 2.0 * vs_.data;
    qs_.data = q + h * vs_.data;
    vs_.data = v + h * a3_.data;
    accelerations(qs_, vs_, a4_);
    vsum += vs_.data;
    q_.data += (h / 6.0) * vsum;
    v_.data += (h / 6.0) * (a1_.data + 2.0 * a2_.data + 2.0 * a3_.data + a4_.data);
  }

  double energy() override {
    // Kinetic: 1/2 v^T H(q) v; potential: -m g z of every centre of mass (z down).
    KDL::JntSpaceInertiaMatrix mass(q_.rows());
    if (params_->JntToMass(q_, mass) < 0) throw std::runtime_error("KDL: JntToMass failed");
    double energy = 0.5 * v_.data.dot(mass.data * v_.data);
    KDL::Frame frame = KDL::Frame::Identity();
    for (unsigned int i = 0; i < chain_.getNrOfSegments(); ++i) {
      const KDL::Segment& segment = chain_.getSegment(i);
      frame = frame * segment.pose(q_(i));
      const double m = segment.getInertia().getMass();
      if (m > 0.0) energy -= spec_.gravity * m * (frame * segment.getInertia().getCOG()).z();
    }
    return energy;
  }

  Eigen::Vector3d tip() override {
    KDL::Frame frame = KDL::Frame::Identity();
    for (unsigned int i = 0; i < chain_.getNrOfSegments(); ++i) frame = frame * chain_.getSegment(i).pose(q_(i));
    return {frame.p.x(), frame.p.y(), frame.p.z()};
  }

 private:
  void accelerations(const KDL::JntArray& q, const KDL::JntArray& v, KDL::JntArray& a) {
    if (solver_->CartToJnt(q, v, zero_, external_, a) < 0) throw std::runtime_error("KDL: ChainFdSolver_RNE failed");
  }

  ChainSpec spec_;
  KDL::Chain chain_;
  std::unique_ptr<KDL::ChainFdSolver_RNE> solver_;
  std::unique_ptr<KDL::ChainDynParam> params_;
  KDL::Wrenches external_;
  KDL::JntArray q0_, q_, v_, qs_, vs_, a1_, a2_, a3_, a4_, zero_;
  Eigen::VectorXd sum_;
};

}  // namespace

std::unique_ptr<System> makeKdl(const ChainSpec& spec) { return std::make_unique<KdlSystem>(spec); }

}  // namespace bench
