#include "cable_dynamics/dynamics/chain_model.h"

namespace cable_dynamics {

ChainModel::ChainModel(const CableParams& params)
    : n_(params.links),
      properties_(deriveLinkProperties(params)),
      formulation_(params.simulation.formulation),
      fluid_density_(params.fluid.density),
      drag_(params.fluid, params.diameter),
      lanes_((params.links + kBlockLanes - 1) / kBlockLanes) {
  const LinkProperties& p = properties_;
  has_springs_ = p.stiffness_elevation.any() || p.stiffness_azimuth.any() || p.stiffness_torsion.any() ||
                 p.damping_elevation.any() || p.damping_azimuth.any() || p.damping_torsion.any();
  load_.mass = p.load_mass;
  load_.inertia = p.load_mass + params.load.added_mass;
  load_.weight = p.gravity * p.load_submerged_mass;
  load_.drag_area = params.load.drag_area;
  load_.coupling_stiffness = params.load.coupling_stiffness;
  load_.coupling_damping = params.load.coupling_damping;

  const double added = p.added_mass_per_length, radius = p.radius;
  for (int b = 0; b < blocks(); ++b) {
    LinkConstants& c = lanes_[b];
    c = LinkConstants{};  // padding lanes: zero length and mass, 1/I_P = 0; they add nothing anywhere
    for (int i = 0; i < kBlockLanes; ++i) {
      const int k = b * kBlockLanes + i;
      if (k >= n_) continue;
      const double l = p.length(k);
      c.length[i] = l;
      c.mass_per_length[i] = p.mass(k) / l;
      c.added[i] = added;
      c.across[i] = c.mass_per_length[i] + added;
      c.weight[i] = p.gravity * p.submerged_mass(k);
      c.half_moment[i] = 0.5 * l * l * c.across[i];
      c.third_moment[i] = l * l * l / 3.0 * c.across[i];
      // The translation integral over the link already holds m l^2/12; the rest of I_T is the thickness.
      c.thick_transverse[i] = p.mass(k) * (radius * radius / 4.0);
      c.own_transverse[i] = c.third_moment[i] + c.thick_transverse[i];
      c.polar[i] = p.inertia_polar(k);
      c.inverse_polar[i] = 1.0 / p.inertia_polar(k);
    }
  }
}

}  // namespace cable_dynamics
