// Live tuning of the simulator's coefficients (CableSimulator::retune): outside the hot step.
#include <stdexcept>
#include <string>

#include "cable_dynamics/params/input_gate.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/tunable_keys.h"

namespace cable_dynamics {

const std::array<TunableKey, 5> kTunableKeys = {{
    {"fluid.drag_normal", [](CableParams& p) -> double& { return p.fluid.drag_normal; },
     [](SectionParams& s) -> double& { return s.drag_normal; }},
    {"fluid.drag_tangential", [](CableParams& p) -> double& { return p.fluid.drag_tangential; },
     [](SectionParams& s) -> double& { return s.drag_tangential; }},
    {"fluid.added_mass", [](CableParams& p) -> double& { return p.fluid.added_mass; },
     [](SectionParams& s) -> double& { return s.added_mass; }},
    {"load.coupling.stiffness", [](CableParams& p) -> double& { return p.load.coupling_stiffness; }, nullptr},
    {"load.coupling.damping", [](CableParams& p) -> double& { return p.load.coupling_damping; }, nullptr},
}};

void CableSimulator::retune(const CableParams& tuned) {
  const CableParams params = ChainModel::withDrumSlots(tuned);  // the config's or the model's copy alike
  if (params.links != params_.links || params.sections.size() != params_.sections.size()) {
    throw std::invalid_argument("retune: the tuned parameters describe another cable (" +
                                std::to_string(params.links) + " links, " + std::to_string(params.sections.size()) +
                                " sections) than the running one (" + std::to_string(params_.links) + " links, " +
                                std::to_string(params_.sections.size()) + " sections)");
  }
  // Only the tunable keys change (kTunableKeys); everything else stays as the simulator was built.
  CableParams next = params_, given = params;
  for (const TunableKey& k : kTunableKeys) {
    k.in(next) = k.in(given);
    if (k.in_section == nullptr) continue;
    for (std::size_t i = 0; i < next.sections.size(); ++i) k.in_section(next.sections[i]) = k.in_section(given.sections[i]);
  }

  // Built and checked aside, so that a refusal leaves the running model as it was; the ranges before
  // the model is built from them.
  checkConfigRanges(next);
  // The coupling spring's extension now (tip - target - rest shift) [m]: a new stiffness is applied bumplessly
  // (EndConditions::shiftCouplingRest), so its force at this extension must be known before the model changes.
  const EndInputs ends = ends_.at(time_);
  const bool spring_coupled = ends.load_coupled && !dynamics_.model().heldTip();
  const double old_stiffness = dynamics_.model().load().coupling_stiffness;
  Eigen::Vector3d tip_from_target = Eigen::Vector3d::Zero();
  if (spring_coupled) {
    dynamics_.computeLoads(x_, ends);
    tip_from_target = dynamics_.data().tip_position - ends.target_position;
  }
  const ChainModel model(next);
  ChainDeployment deployed = dynamics_.deployed();  // the running deployment, with the new constants
  model.redeploy(deployed);
  checkSimulatorInputs(next, deployed.properties(), use_);  // the gate; the coupling's rate enters RK4's limit
  dynamics_.replaceModel(model, deployed);  // the deployment checked above: redeployed once
  params_ = next;
  const double new_stiffness = dynamics_.model().load().coupling_stiffness;
  if (spring_coupled && new_stiffness != old_stiffness && new_stiffness > 0.0) {
    // k_new (d - s_new) = k_old (d - s_old), d the tip's offset from the target: the force stays as it was.
    const Eigen::Vector3d extension = tip_from_target - ends.coupling_rest_shift;
    ends_.shiftCouplingRest(tip_from_target - (old_stiffness / new_stiffness) * extension, time_);
  }
  // A scheme that kept an evaluation of the old model (the last step's end) must evaluate afresh.
  scheme_->forget();
  start_balance_known_ = false;
}

}  // namespace cable_dynamics
