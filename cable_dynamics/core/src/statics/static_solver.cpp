#include "cable_dynamics/statics/static_solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/LU>

#include "cable_dynamics/dynamics/joint_geometry.h"
#include "cable_dynamics/dynamics/state_layout.h"
#include "static_equations.h"
#include "catenary_start.h"
#include "static_newton.h"
#include "static_start.h"

namespace cable_dynamics {
namespace {

using statics::StaticEquations;
using statics::StaticNewton;
using statics::StaticState;

/// Why the model or the problem has no solution here, or empty.
std::string refusal(const ChainModel& model, const ChainDeployment& deployed, const StaticProblem& problem,
                    const StaticEquations* eq) {
  std::ostringstream text;
  if (problem.first_link < 0 || problem.first_link >= model.links()) {
    text << "no deployed link: first_link " << problem.first_link << " of " << model.links() << " links";
    return text.str();
  }
  const LinkProperties& p = deployed.properties();
  if (model.stiffnessModel() == StiffnessModel::kPaper &&
      (p.stiffness_elevation.any() || p.stiffness_azimuth.any() || p.stiffness_torsion.any())) {
    return "the paper stiffness model's springs are not supported by the statics (use the bending model, or no springs)";
  }
  if (eq != nullptr && problem.tip_coupled) {
    const double distance = (problem.target_position - problem.base_position).norm(), length = eq->deployedLength();
    if (distance > length) {
      text << "no equilibrium: the target is " << distance << " m from the base and the deployed cable is " << length
           << " m long";
      return text.str();
    }
  }
  return "";
}

/// The guess without springs: the swept limp chain, shot onto the coupling spring when coupled.
bool limpStart(const StaticEquations& eq, StaticState& s, std::string& why) {
  if (eq.problem().tip_coupled) return statics::shootCoupled(eq, s, why);
  statics::straightStart(eq, Eigen::Vector3d::UnitZ(), s);  // the fixed points' first guesses, the depths
  statics::sweepLimp(eq, Eigen::Vector3d::Zero(), s);
  return true;
}

/// Newton with a scale ramped up from `first` to 1 (the bend springs' or the seabed's: `set_scale`),
/// each step's solution the next one's start, a step that fails retried at the geometric mean.
template <typename SetScale>
bool continuation(SetScale set_scale, double first, const char* what, StaticNewton& newton, StaticState& s,
                  const StaticOptions& options, int& iterations, double& residual, std::string& why) {
  StaticState saved = s;
  double done = 0.0, next = first;
  for (int attempt = 0; attempt < 60; ++attempt) {
    set_scale(next);
    int taken = 0;
    const bool ok = newton.solve(s, options.tolerance, options.max_iterations, taken, residual, why);
    iterations += taken;
    if (ok) {
      if (next == 1.0) return true;
      saved = s;
      done = next;
      next = std::min(1.0, next * 4.0);
    } else {
      s = saved;
      next = done > 0.0 ? std::sqrt(done * next) : next * 0.1;
      if (next <= done * 1.0001) break;
    }
  }
  set_scale(1.0);
  why = std::string("the ") + what + " continuation stalled: " + why;
  return false;
}

void writeSolution(const ChainModel& model, const ChainDeployment& deployed, const StaticEquations& eq, const StaticState& s,
                   StaticSolution& out) {
  const int n = model.links(), first = eq.problem().first_link;
  const LinkProperties& p = deployed.properties();
  out.axes = Eigen::Matrix3Xd::Zero(3, n);
  out.axes.row(2).setOnes();
  out.twists = Eigen::VectorXd::Zero(n);
  out.tension = Eigen::VectorXd::Zero(n);
  out.joint_force = Eigen::Matrix3Xd::Zero(3, n);
  out.far_drag = Eigen::VectorXd::Zero(n);
  // Zero twist at every joint: sigma_k = sigma_{k-1} + Omega(u_{k-1}, u_k), from the clamp's frame.
  Eigen::Vector3d prev = eq.problem().clamp_moves ? eq.problem().clamp_axis : p.clamp_axis;
  double sigma = eq.problem().clamp_moves ? eq.problem().clamp_twist : p.clamp_twist;
  for (int i = 0; i < eq.links(); ++i) {
    const int k = first + i;
    const Eigen::Vector3d u = s.axis.col(i);
    sigma += transportHolonomy(prev.x(), prev.y(), prev.z(), u.x(), u.y(), u.z());
    out.axes.col(k) = u;
    out.twists(k) = sigma;
    out.joint_force.col(k) = s.force.col(i);
    out.tension(k) = -s.force.col(i).dot(u);
    out.far_drag(k) = eq.farDrag(i, u, s.base.col(i));
    prev = u;
  }
  out.tip_position = eq.tip(s);
  out.tip_force = eq.outboardForce(s, eq.links() - 1);
  out.hold_force = eq.couplingForce(out.tip_position);
}

/// Without the seabed's contact (the scale eq has): the limp or spring-loaded problem.
bool solveWithoutContact(StaticEquations& eq, StaticNewton& newton, StaticState& s, const StaticOptions& options,
                         StaticSolution& out, std::string& why) {
  int taken = 0;
  bool ok = false;
  if (!eq.hasBendSprings()) {
    // Limp: the sweep is the answer up to the drag's fixed points and a profile's depths; Newton polishes.
    std::string start_why;
    const bool started = limpStart(eq, s, start_why);
    ok = newton.solve(s, options.tolerance, options.max_iterations, taken, out.residual, why);
    out.iterations += taken;
    if (!ok && !started) why += " (from a poor start: " + start_why + ")";
  } else {
    // Springs: a free tip starts straight along the clamp (the small-deflection answer's neighbour), a
    // coupled one from the limp chain that meets the target; if Newton stalls there, ramp the springs up.
    if (eq.problem().tip_coupled) {
      limpStart(eq, s, why);
    } else {
      statics::straightStart(eq, eq.clampAxis(), s);
    }
    ok = newton.solve(s, options.tolerance, options.max_iterations, taken, out.residual, why);
    out.iterations += taken;
    if (!ok) {
      eq.setStiffnessScale(0.0);
      limpStart(eq, s, why);
      ok = continuation([&eq](double scale) { eq.setStiffnessScale(scale); }, 1e-3, "stiffness", newton, s, options,
                        out.iterations, out.residual, why);
    }
  }
  return ok;
}

}  // namespace

namespace {

/// Newton iterations a warm start (the last sweep's equilibrium) is given before the cold path.
constexpr int kWarmIterations = 20;

/// The equilibrium with each link's lever l + problem.stretch (rigid links when it is empty).
/// `reach_target`: the problem's own target (the anchor's reach is checked on it), or one an exact anchor's
/// sweeps have shifted beyond the anchor by the hold's give (checked on `reach_target`).
StaticSolution solveAtStretch(const ChainModel& model, const ChainDeployment& deployed, const CurrentField& current,
                              const StaticProblem& problem, const StaticOptions& options,
                              const Eigen::Vector3d* reach_target = nullptr, StaticState* warm = nullptr) {
  StaticSolution out;
  out.message = refusal(model, deployed, problem, nullptr);
  if (!out.message.empty()) return out;
  StaticEquations eq(model, deployed, current, problem);
  StaticProblem reach = problem;
  if (reach_target != nullptr) reach.target_position = *reach_target;
  out.message = refusal(model, deployed, reach, &eq);
  if (!out.message.empty()) return out;

  StaticState s;
  s.resize(eq.links());
  StaticNewton newton(eq);
  std::string why;
  bool ok = false;
  if (warm != nullptr && warm->axis.cols() == eq.links()) {
    // A later sweep of solveStatics' fixed points: the last sweep's equilibrium, with every spring and the
    // bed at full strength, is a Newton start one small shift away (the stretches and the hold's target
    // moved by their fixed points' steps). Where it does not converge within kWarmIterations, the cold path
    // below starts afresh. At least one iteration: a start already within the tolerance would leave the tip
    // where it was, and the anchor's secant would read that its target's shift moved nothing.
    s = *warm;
    int taken = 0;
    ok = newton.solve(s, options.tolerance, std::min(kWarmIterations, options.max_iterations), taken, out.residual, why,
                      1);
    out.iterations += taken;
  }
  if (!ok) {
    // With a seabed: first the cable as if the bed were not there; where it hangs through the bed, the
    // bed's springs are ramped up from 1e-4 of their stiffness, lifting it out step by step.
    if (eq.hasSeabed()) eq.setContactScale(0.0);
    ok = solveWithoutContact(eq, newton, s, options, out, why);
    if (ok && eq.hasSeabed()) {
      eq.setContactScale(1.0);
      if (eq.touchesSeabed(s)) {
        ok = continuation([&eq](double scale) { eq.setContactScale(scale); }, 1e-4, "seabed contact", newton, s, options,
                          out.iterations, out.residual, why);
      }
    }
  }
  if (ok && warm != nullptr) *warm = s;
  out.converged = ok;
  out.message = ok ? "" : why;
  writeSolution(model, deployed, eq, s, out);
  return out;
}

/// The tension in link k's stretch in a solution, T_k = -(J_{k+1} - w_f e_z) . u_k + f_d: what is outboard
/// of joint k + 1 (the load's pull at the last), the far-end point's weight w_f and the far half's skin
/// friction f_d (docs/MODEL.md section 12) [N].
double farEndTension(const ChainDeployment& deployed, const StaticSolution& solved, int k, int n) {
  const Eigen::Vector3d outboard = k + 1 < n ? Eigen::Vector3d(solved.joint_force.col(k + 1)) : solved.tip_force;
  const double far_weight = deployed.get(&LinkConstants::far_weight, k);
  const double far_drag = solved.far_drag.size() > k ? solved.far_drag(k) : 0.0;
  return -outboard.dot(solved.axes.col(k)) + far_weight * solved.axes(2, k) + far_drag;
}

/// Each link's stretch under the tension at its far end (farEndTension), tension only, for the axial
/// springs T = EA / l s (a locked last link stays rigid).
Eigen::VectorXd stretchUnderTension(const ChainModel& model, const ChainDeployment& deployed, const StaticSolution& solved,
                                    int first) {
  const int n = model.links();
  Eigen::VectorXd stretch = Eigen::VectorXd::Zero(n);
  for (int k = first; k < n; ++k) {
    const double tension = farEndTension(deployed, solved, k, n);
    const double spring = deployed.get(&LinkConstants::axial_stiffness, k);
    stretch(k) = spring > 0.0 && tension > 0.0 ? tension / spring : 0.0;
  }
  return stretch;
}

/// A stretching link in compression is no equilibrium of a tension-only cable (its links telescope
/// freely while slack): a solve that ends there started into a kink the rigid-link solve can hold (seen
/// where a 0.5 m link met the touchdown of a line graded 1.25 / 0.5 / 6.5 m, its top tension 13 % high).
/// Marks `solved` as not converged, naming the link and its compression, beyond 1e-6 of the largest tension.
void refuseCompression(const ChainModel& model, const ChainDeployment& deployed, int first, StaticSolution& solved) {
  const int n = model.links();
  double largest = 0.0, most = 0.0;
  int where = -1;
  for (int k = first; k < n; ++k) {
    const double tension = farEndTension(deployed, solved, k, n);
    largest = std::max(largest, std::abs(tension));
    if (deployed.get(&LinkConstants::axial_stiffness, k) > 0.0 && tension < most) {
      most = tension;
      where = k;
    }
  }
  if (where < 0 || -most <= 1e-6 * largest) return;
  solved.converged = false;
  solved.message = "the elastic equilibrium found has link " + std::to_string(where + 1) + " in compression (" +
                   std::to_string(-most) + " N), which a tension-only cable cannot hold: a kink the solve started "
                   "into (try other link lengths near the touchdown, or initial.mode: angles and let it settle)";
}

}  // namespace

StaticSolution solveStatics(const ChainModel& model, const ChainDeployment& deployed, const CurrentField& current,
                            const StaticProblem& problem,
                            const StaticOptions& options) {
  const bool held = problem.tip_coupled && model.holdStiffness() > 0.0;
  if (!model.axial() && !held) return solveAtStretch(model, deployed, current, problem, options);
  // Two fixed points in one loop, each sweep a solve:
  // - the elastic equilibrium: solve with the levers l + s, stretch each link under its far end's tension,
  //   repeat. Each sweep changes the tensions by the stretch's share of the line's compliance (about
  //   T L / EA of the geometry: 0.04 for a taut 410 m chain at 1 MN), so it contracts fast for a cable;
  // - an exact anchor: the statics' hold (staticHoldStiffness) leaves the tip f / k short of the anchor;
  //   its target moves by Broyden's secant steps on the map target -> tip (starting from the identity, a
  //   hold far stiffer than the line at the tip), and the tip lands on the anchor in a few sweeps. The
  //   hold then carries exactly the anchor's reaction.
  // Stopped when the stretches and the tip move by less than 1e-12 of the length.
  StaticProblem sweep_problem = problem;
  if (model.axial()) sweep_problem.stretch = Eigen::VectorXd::Zero(model.links());
  const double length = deployed.properties().length.sum();
  constexpr int kMaxSweeps = 100;
  StaticSolution out;
  Eigen::Matrix3d secant = Eigen::Matrix3d::Identity();  // d tip / d target, Broyden's estimate
  Eigen::Vector3d last_shift = Eigen::Vector3d::Zero(), last_tip = Eigen::Vector3d::Zero();
  statics::StaticState warm;  // the last sweep's equilibrium: the next one's start
  // A limp uniform line on an exact anchor starts from its elastic catenary: its shape, its stretches and
  // the hold's target that carries its anchor's pull (catenary_start.h); the first sweep is then a warm one.
  Eigen::VectorXd catenary_stretch;
  if (options.catenary_start && statics::catenaryStart(model, deployed, current, sweep_problem, warm, catenary_stretch,
                                     sweep_problem.target_position)) {
    if (model.axial()) sweep_problem.stretch = catenary_stretch;
  }
  for (int sweep = 1; sweep <= kMaxSweeps; ++sweep) {
    const int iterations = out.iterations;
    out = solveAtStretch(model, deployed, current, sweep_problem, options, &problem.target_position, &warm);
    out.iterations += iterations;
    out.elastic_sweeps = model.axial() ? sweep : 0;
    if (!out.converged) return out;
    double change = 0.0;
    if (model.axial()) {
      const Eigen::VectorXd next = stretchUnderTension(model, deployed, out, problem.first_link);
      change = (next - sweep_problem.stretch).cwiseAbs().maxCoeff();
      sweep_problem.stretch = next;
    }
    if (held) {
      const Eigen::Vector3d miss = problem.target_position - out.tip_position;
      change = std::max(change, miss.cwiseAbs().maxCoeff());
      if (sweep > 1 && last_shift.squaredNorm() > 0.0) {  // Broyden's update on the last shift's effect
        const Eigen::Vector3d moved = out.tip_position - last_tip;
        secant += (moved - secant * last_shift) * last_shift.transpose() / last_shift.squaredNorm();
      }
      last_shift = secant.fullPivLu().solve(miss);
      if (!last_shift.allFinite()) last_shift = miss;
      last_tip = out.tip_position;
      sweep_problem.target_position += last_shift;
    }
    if (change <= 1e-12 * length) {
      if (model.axial()) {
        out.stretch = sweep_problem.stretch;
        refuseCompression(model, deployed, problem.first_link, out);
      }
      return out;
    }
  }
  out.converged = false;
  out.message = std::string(model.axial() ? "the elastic equilibrium's stretches" : "the anchored tip") +
                " did not settle in " + std::to_string(kMaxSweeps) +
                " sweeps (an EA so low that the line's shape follows its stretch, or a tip the line cannot reach)";
  return out;
}

void setRestState(const StaticSolution& solution, Eigen::VectorXd& x) {
  const int n = static_cast<int>(solution.twists.size());
  for (int k = 0; k < n; ++k) {
    x.segment<3>(StateLayout::axis(k)) = solution.axes.col(k);
    x(StateLayout::twist(k)) = solution.twists(k);
    x.segment<3>(StateLayout::omega(k)).setZero();
  }
  if (solution.stretch.size() == n && n > 0) {  // the state's last 2n entries: stretches, then their rates
    x.segment(x.size() - 2 * n, n) = solution.stretch;
    x.tail(n).setZero();
  }
}

}  // namespace cable_dynamics
