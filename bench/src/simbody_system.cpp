// Simbody 3.7 (Debian's libsimbody-dev): MobilizedBody::Ball chain (quaternion q, 4 per joint;
// angular velocity u, 3 per joint), gravity by Force::Gravity, forward dynamics by
// realize(state, Stage::Acceleration) (Simbody's O(n) articulated-body recursion), and a hand-written
// fixed-step classical RK4 on (q, u) with Simbody's own kinematic map qdot = N(q) u (State::getQDot())
// at every stage. Simbody has no classical RK4 (its explicit integrators are RK2, RK3, Merson with
// 5 evaluations and Feldberg with 6), hence the hand-written one. The quaternions are integrated as
// 4-vectors and renormalized once per step, as Simbody's integrators do when they project the state.
#include <Simbody.h>

#include "chain_spec.h"

namespace bench {
namespace {

class SimbodySystem : public System {
 public:
  explicit SimbodySystem(const ChainSpec& spec) : spec_(spec), matter_(system_), forces_(system_) {
    SimTK::Force::Gravity(forces_, matter_, SimTK::UnitVec3(0, 0, 1), spec.gravity);
    SimTK::MobilizedBody parent = matter_.Ground();
    for (int k = 0; k < spec.n; ++k) {
      const double m = spec.bodyMass(k), it = spec.bodyInertiaTransverse(k);
      const SimTK::Vec3 com(0, 0, spec.bodyCom(k));
      // Simbody takes the inertia about the body origin (here the joint): shift it from the mass centre.
      const SimTK::Inertia about_origin = SimTK::Inertia(it, it, spec.bodyInertiaPolar(k)).shiftFromMassCenter(com, m);
      const SimTK::Body::Rigid body(SimTK::MassProperties(m, com, about_origin));
      const SimTK::Transform in_parent(SimTK::Vec3(0, 0, k == 0 ? 0.0 : spec.length[k - 1]));
      SimTK::MobilizedBody::Ball ball(parent, in_parent, body, SimTK::Transform());
      balls_.push_back(ball);
      parent = ball;
    }
    system_.realizeTopology();
    initial_ = system_.getDefaultState();
    system_.realizeModel(initial_);
    for (int k = 0; k < spec.n; ++k) {
      const Eigen::Matrix3d r = spec.relativeRotation(k);
      SimTK::Mat33 m;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = r(i, j);
      balls_[k].setQToFitRotation(initial_, SimTK::Rotation(m));
    }
    initial_.updU() = 0;
    state_ = initial_;
    system_.realize(state_, SimTK::Stage::Acceleration);
    quaternion_start_.clear();
    for (int k = 0; k < spec.n; ++k) quaternion_start_.push_back(balls_[k].getFirstQIndex(state_));
    const int nq = state_.getNQ(), nu = state_.getNU();
    for (SimTK::Vector* v : {&q0_, &qs_, &qsum_}) v->resize(nq);
    for (SimTK::Vector* v : {&u0_, &us_, &usum_}) v->resize(nu);
  }

  void reset() override {
    state_ = initial_;
    system_.realize(state_, SimTK::Stage::Acceleration);
  }

  void step() override {
    const double h = spec_.dt;
    const int nq = q0_.size(), nu = u0_.size();
    q0_ = state_.getQ();
    u0_ = state_.getU();
    // Stage 1 at the state as it is.
    evaluate(q0_, u0_);
    const SimTK::Vector* qdot = &state_.getQDot();
    const SimTK::Vector* udot = &state_.getUDot();
    // Stages 2-4: x_s = x0 + c h k_{s-1}; sums of k1 + 2 k2 + 2 k3 + k4 kept as they come.
    const double c[3] = {0.5 * h, 0.5 * h, h}, w[3] = {2.0, 2.0, 1.0};
    for (int i = 0; i < nq; ++i) qsum_[i] = (*qdot)[i];
    for (int i = 0; i < nu; ++i) usum_[i] = (*udot)[i];
    for (int s = 0; s < 3; ++s) {
      for (int i = 0; i < nq; ++i) qs_[i] = q0_[i] + c[s] * (*qdot)[i];
      for (int i = 0; i < nu; ++i) us_[i] = u0_[i] + c[s] * (*udot)[i];
      evaluate(qs_, us_);
      qdot = &state_.getQDot();
      udot = &state_.getUDot();
      for (int i = 0; i < nq; ++i) qsum_[i] += w[s] * (*qdot)[i];
      for (int i = 0; i < nu; ++i) usum_[i] += w[s] * (*udot)[i];
    }
    SimTK::Vector& q = state_.updQ();
    for (int i = 0; i < nq; ++i) q[i] = q0_[i] + (h / 6.0) * qsum_[i];
    for (int start : quaternion_start_) {
      double norm = 0.0;
      for (int i = 0; i < 4; ++i) norm += q[start + i] * q[start + i];
      norm = std::sqrt(norm);
      for (int i = 0; i < 4; ++i) q[start + i] /= norm;
    }
    SimTK::Vector& u = state_.updU();
    for (int i = 0; i < nu; ++i) u[i] = u0_[i] + (h / 6.0) * usum_[i];
    // Leaves the state realized through Acceleration for the next step's first stage.
    system_.realize(state_, SimTK::Stage::Acceleration);
  }

  double energy() override {
    system_.realize(state_, SimTK::Stage::Dynamics);
    return system_.calcEnergy(state_);
  }

  Eigen::Vector3d tip() override {
    system_.realize(state_, SimTK::Stage::Position);
    const SimTK::Vec3 p = balls_.back().findStationLocationInGround(state_, SimTK::Vec3(0, 0, spec_.length.back()));
    return {p[0], p[1], p[2]};
  }

 private:
  /// Forward dynamics at (q, u): afterwards state_ holds qdot = N(q) u and udot.
  void evaluate(const SimTK::Vector& q, const SimTK::Vector& u) {
    state_.updQ() = q;
    state_.updU() = u;
    system_.realize(state_, SimTK::Stage::Acceleration);
  }

  ChainSpec spec_;
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  std::vector<SimTK::MobilizedBody::Ball> balls_;
  SimTK::State initial_, state_;
  std::vector<int> quaternion_start_;
  SimTK::Vector q0_, u0_, qs_, us_, qsum_, usum_;
};

}  // namespace

std::unique_ptr<System> makeSimbody(const ChainSpec& spec) { return std::make_unique<SimbodySystem>(spec); }

}  // namespace bench
