#pragma once
// dV/dq of the joint springs by central differences of the dynamics' own elastic energy (joint_torques.cpp's
// elasticEnergy, from the joints' geometry) on the paper coordinates q, with the base's clamp held where
// `clamp_axis`, `clamp_twist` put it: a truth for the spring forces the snapshot maps from the joint
// torques (a separate computation). h = 1e-6 rad: truncation O(h^2 V''') and round-off O(eps V / h) both
// near 1e-9 of the largest force for these cables.
#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_dynamics.h"

namespace cable_dynamics {

inline Eigen::VectorXd springGradientByDifferences(const CableParams& params, const Eigen::VectorXd& q,
                                                   const Eigen::Vector3d& clamp_axis, double clamp_twist) {
  ChainDynamics probe(params);
  const int n = probe.links();
  EndInputs ends;
  ends.clamp_moves = true;
  ends.clamp_axis = clamp_axis;
  ends.clamp_twist = clamp_twist;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3 * n);
  Eigen::VectorXd x(probe.stateSize()), shifted = q, gradient(3 * n);
  ChainOutputs out;
  const auto energy = [&](const Eigen::VectorXd& at) {
    probe.stateFromPaper(at, rest, x);
    probe.evaluate(x, ends, out);
    return out.elastic_energy;
  };
  const double h = 1e-6;
  for (int i = 0; i < 3 * n; ++i) {
    shifted(i) = q(i) + h;
    const double plus = energy(shifted);
    shifted(i) = q(i) - h;
    const double minus = energy(shifted);
    shifted(i) = q(i);
    gradient(i) = (plus - minus) / (2.0 * h);
  }
  return gradient;
}

}  // namespace cable_dynamics
