#include "cable_dynamics/dynamics/kinematics.h"

#include <cmath>

#include "cable_dynamics/dynamics/hot_path.h"

namespace cable_dynamics {

CABLE_HOT_PATH void computeKinematics(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x,
                                      const EndInputs& ends) {
  const int n = model.links(), first = data.deployed.firstLink();
  LinkBlocks& links = data.links;
  // Three passes, each over the whole chain. The state holds a link's numbers together and a block
  // holds them by kind, so the first pass copies them one by one; a whole pass lies between those
  // scalar stores and the vector loads of the second (a vector load right after the scalar stores
  // it spans would wait for them to reach the cache).
  for (int k = first; k < n; ++k) {
    LinkBlock& block = links.of(k);
    const int i = LinkBlocks::lane(k);
    const double* link = x.data() + StateLayout::axis(k);
    block.u.set(i, {link[0], link[1], link[2]});
    block.omega.set(i, {link[4], link[5], link[6]});
  }
  for (int b = data.deployed.firstBlock(); b < links.blocks(); ++b) {
    LinkBlock& block = links.block(b);
    for (int i = 0; i < kBlockLanes; ++i) {
      // Links are unit vectors up to the integrator's drift: use the normalized axis.
      const Vec3 raw = block.u[i], omega = block.omega[i];
      const Vec3 axis = (1.0 / std::sqrt(dot(raw, raw))) * raw;
      const Vec3 axis_rate = cross(omega, axis);
      block.u.set(i, axis);
      block.axis_rate.set(i, axis_rate);
      block.beta.set(i, cross(omega, axis_rate));  // centripetal part of u''
      // sigma = psi + phi: from omega = -psi' e_z - te' n - phi' u, omega.(e_z + u) = -(psi' + phi')(1 + cos te).
      const double denominator = 1.0 + axis.z, spin = dot(omega, axis);
      block.twist_rate[i] = denominator > 1e-12 ? -(omega.z + spin) / denominator : -spin;
    }
  }
  // Base ends: running sums along the chain, from the base link (the drum's slots before it sit at
  // the base). A winch pays the base link's material out along its axis u at the speed v: each of its
  // points moves by v u more and accelerates by v' u + 2 v u' more (docs/MODEL.md section 8), and the
  // links beyond it with them.
  Vec3 pos = toVec3(ends.base_position), vel = toVec3(ends.base_velocity), acc = toVec3(ends.base_acceleration);
  for (int k = data.deployed.firstBlock() * kBlockLanes; k < first; ++k) {  // the idle lanes the block loops read
    LinkBlock& block = links.of(k);
    const int i = LinkBlocks::lane(k);
    block.base_pos.set(i, pos);
    block.base_vel.set(i, vel);
    block.known_acc.set(i, acc);
  }
  if (ends.winch) {
    const LinkBlock& block = links.of(first);
    const int i = LinkBlocks::lane(first);
    const Vec3 u = block.u[i];
    vel = vel + ends.winch_speed * u;
    acc = acc + ends.winch_acceleration * u + (2.0 * ends.winch_speed) * block.axis_rate[i];
  }
  for (int k = first; k < n; ++k) {
    LinkBlock& block = links.of(k);
    const int i = LinkBlocks::lane(k);
    block.base_pos.set(i, pos);
    block.base_vel.set(i, vel);
    block.known_acc.set(i, acc);
    // The far end is l + s along u (s = 0 with rigid links: the same numbers to the last bit): it moves
    // by (l + s) u' + s' u, and accelerates by (l + s) beta + 2 s' u' at zero angular and stretch
    // accelerations.
    const double lever = data.deployed.of(k).length[i] + block.stretch[i], rate = block.stretch_rate[i];
    const Vec3 u = block.u[i], axis_rate = block.axis_rate[i];
    pos = pos + lever * u;
    vel = vel + lever * axis_rate + rate * u;
    acc = farEndKnownAcceleration(acc, block.beta[i], axis_rate, lever, rate);
  }
  data.tip_position = toEigen(pos);
  data.tip_velocity = toEigen(vel);
  data.tip_known_acc = toEigen(acc);
}

}  // namespace cable_dynamics
