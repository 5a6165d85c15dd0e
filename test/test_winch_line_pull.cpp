// Issue 27 item 1: the winch's line pull through the links it adds (docs/MODEL.md section 8, "A link
// added"). Paying out, the line pull must be smooth: its deviation from its own 2 s moving average (centred,
// sampled every 10 ms) at most 1 % rms and 3 % at its peak, on config/rov_dive.yaml (a slack soft tether,
// 2 m links added every 2 s at 1 m/s) and on a stiff tether paid out in a current; the winch's energy
// bookkeeping stays closed and the deployed mass is m' L.
//
// Measured (RK4 as configured), before the fix (the new joint released at once) and after (held with the
// rigid link's moment, let go over two links of pay-out):
//   rov_dive.yaml, 20-110 s:                    7.6 % rms, 35.7 % peak  ->  0.32 % rms, 0.58 % peak
//   stiff tether (EI = GJ = 200 N m^2), 8-40 s:  2.8 % rms, 24.6 % peak  ->  0.04 % rms, 0.10 % peak
// Hauling in (links merged into the winch's link) was smooth already: the same stiff tether hauled in at
// 1 m/s, 0.013 % rms, 0.083 % peak (the last test).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"

using namespace cable_dynamics;

namespace {

struct Ripple {
  double rms = 0.0, peak = 0.0;  // [-] of the moving average
  int links_added = 0;           // within the window
  int links_removed = 0;         // within the window
  double energy_drift = 0.0;     // the simulator's energyDrift() at the end
  double mass_error = 0.0;       // largest |deployed mass - m' L| [kg] at the samples
};

/// Runs `sim` to `to` + 1 s, sampling its line pull every 10 ms, and measures the line pull's deviation
/// from its centred 2 s moving average over [from, to] (relative to the average).
Ripple linePullRipple(CableSimulator& sim, double mass_per_length, double from, double to) {
  const double sample = 0.01;
  const long per_sample = std::lround(sample / sim.dt());
  std::vector<double> t, pull;
  Ripple out;
  SimulationSnapshot snap;
  int added_before = -1, removed_before = -1;
  while (sim.time() < to + 1.0 + 0.5 * sample) {
    sim.snapshot(snap);
    t.push_back(sim.time());
    pull.push_back(snap.line_pull);
    out.mass_error = std::max(out.mass_error, std::abs(sim.properties().mass.sum() - mass_per_length * sim.deployedLength()));
    if (added_before < 0 && sim.time() >= from) {
      added_before = sim.linksAdded();
      removed_before = sim.linksRemoved();
    }
    for (long i = 0; i < per_sample; ++i) {
      const StepReport r = sim.step();
      if (!r.ok) {
        ADD_FAILURE() << r.message;
        return out;
      }
    }
  }
  out.links_added = sim.linksAdded() - added_before;
  out.links_removed = sim.linksRemoved() - removed_before;
  const int half = static_cast<int>(std::lround(1.0 / sample));  // 1 s each side
  double sum = 0.0;
  int count = 0;
  for (int i = half; i + half < static_cast<int>(t.size()); ++i) {
    if (t[i] < from - 1e-9 || t[i] > to + 1e-9) continue;
    double mean = 0.0;
    for (int j = i - half; j < i + half; ++j) mean += pull[j];
    mean /= 2 * half;
    const double deviation = (pull[i] - mean) / mean;
    sum += deviation * deviation;
    ++count;
    out.peak = std::max(out.peak, std::abs(deviation));
  }
  out.rms = std::sqrt(sum / std::max(count, 1));
  out.energy_drift = sim.energyDrift();
  return out;
}

void report(const char* name, const Ripple& r) {
  std::cout << name << ": line pull " << 100.0 * r.rms << " % rms, " << 100.0 * r.peak
            << " % peak about its 2 s moving average; " << r.links_added << " links added, " << r.links_removed
            << " removed; energy drift "
            << r.energy_drift << "; mass error " << r.mass_error << " kg" << std::endl;
}

// The thresholds: the requirement (1 % rms, 3 % peak), or tighter where the measure is far below
// it, so that each stays 3x to 10x above what is measured.
constexpr double kRovDiveRms = 0.01, kRovDivePeak = 0.03;  // measured 0.32 % rms, 0.57 % peak: 3.1x, 5.3x
constexpr double kStiffRms = 0.003, kStiffPeak = 0.01;     // measured 0.04 % rms, 0.10 % peak: 7.5x, 10x

/// The checks both cases make: enough links added, the ripple within its bounds, the energy balance and the
/// deployed mass exact (the hold's power is booked: drift measured 2e-12 to 4e-12; cable_sim's limit 1e-3).
void expectSmooth(const Ripple& r, int links_added, double rms, double peak) {
  EXPECT_GE(r.links_added, links_added);
  EXPECT_LT(r.rms, rms);
  EXPECT_LT(r.peak, peak);
  EXPECT_GE(r.energy_drift, 0.0);
  EXPECT_LT(r.energy_drift, 1e-10);
  EXPECT_LT(r.mass_error, 1e-9);
}

}  // namespace

// config/rov_dive.yaml as configured: paid out at 1 m/s from 30 m, a 2 m link added every 2 s, the ROV on
// its stiff coupling descending in a 0.3 m/s current. Before the fix the line pull dipped by 20 to 35 %
// at each link added and rang for 0.5 s.
TEST(WinchLinePull, RovDiveIsSmoothThroughTheLinksAdded) {
  const CableParams p = loadConfigFile(std::string(CABLE_CONFIG_DIR) + "/rov_dive.yaml");
  CableSimulator sim(p);
  const Ripple r = linePullRipple(sim, 0.6, 20.0, 110.0);
  report("rov_dive.yaml, 20-110 s", r);
  expectSmooth(r, 40, kRovDiveRms, kRovDivePeak);
}

// A stiff tether (EI = GJ = 200 N m^2, clamped straight down at the winch) under a 50 kg load in a 0.3 m/s
// current, paid out at 1 m/s from 20 m: 2 m links, one every 2 s.
TEST(WinchLinePull, StiffTetherInACurrentIsSmoothThroughTheLinksAdded) {
  const CableParams p = loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.025, mass_per_length: 0.6,\n"
      "        stiffness: {model: bending, bending_rigidity: 200.0, torsional_rigidity: 200.0}}\n"
      "load: {mass: 50.0, volume: 0.02, drag_area: 0.3}\n"
      "fluid: {current: [0.3, 0.0, 0.0]}\n"
      "winch: {max_length: 70.0, max_speed: 1.0, max_acceleration: 1.0, schedule: [{time: 0.0, speed: 1.0}]}\n"
      "initial: {mode: equilibrium}\n"
      "simulation: {dt: 0.0005}\n");
  CableSimulator sim(p);
  const Ripple r = linePullRipple(sim, 0.6, 8.0, 40.0);
  report("stiff tether in a current, 8-40 s", r);
  expectSmooth(r, 14, kStiffRms, kStiffPeak);
}

// Hauling in (issue 27 item 1's other half): the same stiff tether from 60 m, hauled in at 1 m/s, a 2 m link
// merged into the winch's link every 2 s. On rov_dive the haul-in's deviation measured 1.57 % rms and 11.4 %
// at its peak, but that was the schedule, not the links: it changes the speed every 10 s at 0.2 m/s^2, and
// the line pull follows the cable's inertia and its tangential drag (266 -> 312 -> 300 N as -0.51 m/s
// becomes -0.60 m/s); at the links removed in between the line pull steps by 0.5 N of 280 N, and over the
// windows of steady speed the deviation is 0.063 % rms, 2.9 % peak. Here the speed is steady throughout.
TEST(WinchLinePull, StiffTetherInACurrentIsSmoothThroughTheLinksRemoved) {
  const CableParams p = loadConfigString(
      "cable: {links: 30, length: 60.0, diameter: 0.025, mass_per_length: 0.6,\n"
      "        stiffness: {model: bending, bending_rigidity: 200.0, torsional_rigidity: 200.0}}\n"
      "load: {mass: 50.0, volume: 0.02, drag_area: 0.3}\n"
      "fluid: {current: [0.3, 0.0, 0.0]}\n"
      "winch: {max_length: 60.0, min_length: 10.0, max_speed: 1.0, max_acceleration: 1.0, schedule: [{time: 0.0, speed: -1.0}]}\n"
      "initial: {mode: equilibrium}\n"
      "simulation: {dt: 0.0005}\n");
  CableSimulator sim(p);
  const Ripple r = linePullRipple(sim, 0.6, 8.0, 40.0);
  report("stiff tether in a current hauled in, 8-40 s", r);
  EXPECT_GE(r.links_removed, 14);
  EXPECT_LT(r.rms, 1e-3);   // measured 0.013 %: 7.6x
  EXPECT_LT(r.peak, 5e-3);  // measured 0.083 %: 6x
  EXPECT_GE(r.energy_drift, 0.0);
  EXPECT_LT(r.energy_drift, 1e-10);
  EXPECT_LT(r.mass_error, 1e-9);
}
