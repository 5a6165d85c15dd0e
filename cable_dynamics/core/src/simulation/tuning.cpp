// Live tuning of the simulator's coefficients (CableSimulator::retune): outside the hot step.
#include <stdexcept>
#include <string>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/stable_step.h"

namespace cable_dynamics {

void CableSimulator::retune(const CableParams& params) {
  if (params.links != params_.links || params.sections.size() != params_.sections.size()) {
    throw std::invalid_argument("retune: the tuned parameters describe another cable (" +
                                std::to_string(params.links) + " links, " + std::to_string(params.sections.size()) +
                                " sections) than the running one (" + std::to_string(params_.links) + " links, " +
                                std::to_string(params_.sections.size()) + " sections)");
  }
  // Only the tunable keys change; everything else stays as the simulator was built.
  CableParams next = params_;
  next.fluid.drag_normal = params.fluid.drag_normal;
  next.fluid.drag_tangential = params.fluid.drag_tangential;
  next.fluid.added_mass = params.fluid.added_mass;
  for (std::size_t i = 0; i < next.sections.size(); ++i) {
    next.sections[i].drag_normal = params.sections[i].drag_normal;
    next.sections[i].drag_tangential = params.sections[i].drag_tangential;
    next.sections[i].added_mass = params.sections[i].added_mass;
  }
  next.load.coupling_stiffness = params.load.coupling_stiffness;
  next.load.coupling_damping = params.load.coupling_damping;

  // Built and checked aside, so that a refusal leaves the running model as it was.
  const ChainModel model(next, dynamics_.model());
  requireStableTimeStep(next, model.properties());  // the coupling's rate enters RK4's limit
  dynamics_.replaceModel(model);
  params_ = next;
  // A scheme that kept an evaluation of the old model (the last step's end) must evaluate afresh.
  scheme_->forget();
  start_balance_known_ = false;
}

}  // namespace cable_dynamics
