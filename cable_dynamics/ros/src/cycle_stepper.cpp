#include "cable_dynamics/ros/cycle_stepper.h"

namespace cable_dynamics {
namespace {

/// The wall clock is read every this many steps (a read costs ~25 ns, a step of a small cable ~1 us).
constexpr long kDeadlineCheckEvery = 4;

}  // namespace

CycleReport stepCycle(CableSimulator& sim, long wanted, const ros::WallTime& deadline) {
  CycleReport report;
  for (long i = 0; i < wanted; ++i) {
    if (i % kDeadlineCheckEvery == 0 && i > 0 && ros::WallTime::now() >= deadline) {
      report.out_of_time = true;
      break;
    }
    const StepReport step = sim.step();
    if (!step.ok) {
      report.diverged = true;
      report.message = step.message;
      sim.recover();  // initial shape, at rest; time and inputs carry on
      break;
    }
    ++report.steps;
    if (step.substeps > 1) ++report.retried;
  }
  return report;
}

}  // namespace cable_dynamics
