#include "project_system.h"

#include <stdexcept>

#include "cable_dynamics/params/config_loader.h"

namespace bench {

std::vector<std::string> projectFormulations() { return {"paper", "recursive"}; }

namespace {
cable_dynamics::CableParams load(int links, const std::string& formulation) {
  return cable_dynamics::loadConfigString(projectConfig(links), {"simulation.formulation=" + formulation});
}
}  // namespace

ProjectSystem::ProjectSystem(int links, const std::string& formulation)
    : params_(load(links, formulation)), sim_(params_) {
  x0_ = sim_.state();
  xdot_.setZero(x0_.size());
}

std::vector<Eigen::Vector3d> ProjectSystem::initialAxes() const {
  std::vector<Eigen::Vector3d> axes;
  for (int k = 0; k < params_.links; ++k) axes.push_back(x0_.segment<3>(cable_dynamics::StateLayout::axis(k)));
  return axes;
}

void ProjectSystem::reset() {
  sim_.reset();
  failed_since_reset_ = 0;
}

void ProjectSystem::step() {
  const cable_dynamics::StepReport report = sim_.step();
  if (report.substeps > 1) ++retried_steps_;
  if (!report.ok) ++failed_steps_, ++failed_since_reset_;
}

double ProjectSystem::energy() {
  // Base at rest at the origin, no fluid, no coupling: the energy balance is the mechanical energy.
  double magnitude = 0.0;
  return sim_.dynamics().mechanicalEnergy(sim_.state(), cable_dynamics::EndInputs(), magnitude);
}

Eigen::Vector3d ProjectSystem::tip() {
  const cable_dynamics::LinkProperties& p = sim_.dynamics().properties();
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  for (int k = 0; k < p.n; ++k) {
    tip += p.length(k) * sim_.state().segment<3>(cable_dynamics::StateLayout::axis(k)).normalized();
  }
  return tip;
}

std::string ProjectSystem::note() const {
  std::string s;
  // Counted over every step this system made at this n (warm-up, repetitions, agreement run).
  if (retried_steps_ > 0) s += std::to_string(retried_steps_) + " steps retried in substeps (energy or divergence check)";
  if (failed_steps_ > 0) s += (s.empty() ? "" : ", ") + std::to_string(failed_steps_) + " steps FAILED (state kept)";
  return s;
}

void ProjectSystem::derivative() {
  if (!sim_.dynamics().derivative(x0_, cable_dynamics::EndInputs(), xdot_)) {
    throw std::runtime_error("ChainDynamics::derivative() failed at the initial state");
  }
}

bool ProjectSystem::derivativeAtStart(Eigen::VectorXd& xdot) {
  xdot.setZero(x0_.size());
  return sim_.dynamics().derivative(x0_, cable_dynamics::EndInputs(), xdot) && xdot.allFinite();
}

}  // namespace bench
