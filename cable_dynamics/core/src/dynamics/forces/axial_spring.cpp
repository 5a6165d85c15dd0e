#include "cable_dynamics/dynamics/forces/axial_spring.h"

#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

void computeAxialTensions(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, double winch_speed) {
  if (!model.axial()) return;
  const int n = model.links();
  const bool body = model.body().active;
  const double* stretch = x.data() + StateLayout::stretch(n, body, 0);
  const double* rate = x.data() + StateLayout::stretchRate(n, body, 0);
  const int first = data.deployed.firstLink();
  // From the first block: a winch's drum slots in it are idle lanes the block loops read, kept unstretched.
  for (int k = data.deployed.firstBlock() * kBlockLanes; k < n; ++k) {
    LinkBlock& block = data.links.of(k);
    const int i = LinkBlocks::lane(k);
    const LinkConstants& c = data.deployed.of(k);
    // A locked stretch (the last link with nothing beyond it: ChainModel::lastStretchLocked) stays 0.
    const bool locked = k < first || model.stretchLocked(k);
    const double s = locked ? 0.0 : stretch[k], v = locked ? 0.0 : rate[k];
    const double damped = k == first ? AxialSpring::dampedRate(s, v, c.length[i], winch_speed) : v;
    const double t = AxialSpring::tension(c.axial_stiffness[i], c.axial_damping[i], s, damped, c.length[i]);
    block.stretch[i] = s;
    block.stretch_rate[i] = v;
    block.damped_rate[i] = damped;
    block.axial_tension[i] = t;
    block.axial_loss[i] = AxialSpring::loss(c.axial_stiffness[i], s, v, t, c.length[i]);
  }
}

double axialEnergy(const ChainModel& model, const ChainData& data) {
  if (!model.axial()) return 0.0;
  double sum = 0.0;
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) {
    const LinkConstants& c = data.deployed.of(k);
    const int i = LinkBlocks::lane(k);
    sum += AxialSpring::energy(c.axial_stiffness[i], data.links.of(k).stretch[i], c.length[i]);
  }
  return sum;
}

double winchStrainPower(const ChainData& data, double winch_speed) {
  const int first = data.deployed.firstLink();
  const LinkConstants& c = data.deployed.of(first);
  const int i = LinkBlocks::lane(first);
  const double l = c.length[i];
  // At a fixed s, 1/2 EA e^2 / l changes with l (AxialSpring::energyPerLength).
  return l > 0.0 ? winch_speed * AxialSpring::energyPerLength(c.axial_stiffness[i], data.links.of(first).stretch[i], l) : 0.0;
}

double axialLossAtShiftedRates(const ChainModel& model, const ChainData& data, const Eigen::VectorXd& shift) {
  if (!model.axial()) return 0.0;
  double sum = 0.0;
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) {
    const LinkBlock& block = data.links.of(k);
    const LinkConstants& c = data.deployed.of(k);
    const int i = LinkBlocks::lane(k);
    const double s = block.stretch[i];
    const double t = AxialSpring::tension(c.axial_stiffness[i], c.axial_damping[i], s, block.damped_rate[i] + shift(k), c.length[i]);
    sum += AxialSpring::loss(c.axial_stiffness[i], s, block.stretch_rate[i] + shift(k), t, c.length[i]);
  }
  return sum;
}

double axialLoss(const ChainModel& model, const ChainData& data) {
  if (!model.axial()) return 0.0;
  double sum = 0.0;
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) sum += data.links.of(k).axial_loss[LinkBlocks::lane(k)];
  return sum;
}

}  // namespace cable_dynamics
