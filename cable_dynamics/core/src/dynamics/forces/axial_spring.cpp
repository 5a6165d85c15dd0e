#include "cable_dynamics/dynamics/forces/axial_spring.h"

#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

void computeAxialTensions(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x) {
  if (!model.axial()) return;
  const int n = model.links();
  const bool body = model.body().active;
  const double* stretch = x.data() + StateLayout::stretch(n, body, 0);
  const double* rate = x.data() + StateLayout::stretchRate(n, body, 0);
  for (int k = data.deployed.firstLink(); k < n; ++k) {
    LinkBlock& block = data.links.of(k);
    const int i = LinkBlocks::lane(k);
    const LinkConstants& c = data.deployed.of(k);
    // A locked stretch (the last link with nothing beyond it: ChainModel::lastStretchLocked) stays 0.
    const bool locked = model.stretchLocked(k);
    const double s = locked ? 0.0 : stretch[k], v = locked ? 0.0 : rate[k];
    const double t = AxialSpring::tension(c.axial_stiffness[i], c.axial_damping[i], s, v);
    block.stretch[i] = s;
    block.stretch_rate[i] = v;
    block.axial_tension[i] = t;
    block.axial_loss[i] = AxialSpring::loss(c.axial_stiffness[i], s, v, t);
  }
}

double axialEnergy(const ChainModel& model, const ChainData& data) {
  if (!model.axial()) return 0.0;
  double sum = 0.0;
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) {
    sum += AxialSpring::energy(data.deployed.of(k).axial_stiffness[LinkBlocks::lane(k)],
                               data.links.of(k).stretch[LinkBlocks::lane(k)]);
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
