// Issue 24, item 1: cable_dynamics side by side with MoorDyn (linked through its C API, built outside this
// repository; bench/moordyn/run.sh). For each line of lines/ (a MoorDyn input file and a cable_dynamics
// config of the same line):
//   - the step each side takes: MoorDyn's own (its CFL rule, RK2, its default; called once per step, and
//     once per 0.1 s as its chain test calls it), cable_dynamics' RK4 at its recommended step
//     (CableSimulator::estimateStableTimeStep) and its implicit integrator at 10 ms, both with the line's
//     EA and axial damping as MoorDyn's (lines/*.yaml; the payout's winch pays out unstretched length,
//     docs/MODEL.md section 12), and RK4 with rigid links (EA and c_a set to 0: the project before its
//     axial elasticity);
//   - wall time per simulated second of the stepping alone (construction, statics and MoorDyn's initial
//     condition solve are outside the clock), median over [reps] repetitions, the three sides run one
//     after the other in every repetition so that they share the machine's load;
//   - the static fairlead tension and its error against the line's reference (closed forms below, and the
//     quasi-static codes' values MoorDyn's test tests/quasi_static_chain.cpp checks against);
//   - the dynamic fairlead tension's max and min over the run (the chains and the jumper: over the window
//     of the reference series MoorDyn's tests read, under the MoorDyn source dir's tests/Mooring/), and its
//     error.
// Usage: moordyn_bench <lines dir> [reps] [MoorDyn source dir or ""]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <moordyn/MoorDyn2.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "mute_stdout.h"

namespace {

using cable_dynamics::CableParams;
using cable_dynamics::CableSimulator;
using Clock = std::chrono::steady_clock;

constexpr double kPi = 3.14159265358979323846;
constexpr double kSample = 0.1;  // s: both sides are sampled (and MoorDyn is driven) every 0.1 s

// ---- the references -----------------------------------------------------------------------------
// The elastic catenary (Irvine, Cable Structures, 1981, ch. 2; with a grounded part the form MAP++
// solves). A line of unstretched length L [m], submerged weight w [N/m], axial stiffness
// EA [N] (infinite: inextensible), from its lower end to a fairlead x out and z up [m]; unknowns the
// horizontal tension H [N] and the fairlead's vertical tension V [N]. With s = asinh:
//  suspended (lower end's vertical tension Va = V - w L):
//    x = H/w (s(V/H) - s(Va/H)) + H L/EA
//    z = H/w (sqrt(1 + (V/H)^2) - sqrt(1 + (Va/H)^2)) + (V L - w L^2/2)/EA
//  a grounded part on a frictionless flat bottom, the anchor on it (0 < V < w L, grounded length L - V/w):
//    x = L - V/w + H/w s(V/H) + H L/EA
//    z = H/w (sqrt(1 + (V/H)^2) - 1) + V^2/(2 w EA)
// Solved by Newton's method in (log H, log V). Returns the fairlead tension sqrt(H^2 + V^2) [N].
double catenaryFairleadTension(double L, double w, double EA, double x, double z, bool grounded) {
  auto residual = [&](double H, double V, double r[2]) {
    const double e = std::isinf(EA) ? 0.0 : 1.0 / EA;
    if (grounded) {
      r[0] = L - V / w + H / w * std::asinh(V / H) + H * L * e - x;
      r[1] = H / w * (std::sqrt(1 + V * V / (H * H)) - 1) + V * V / (2 * w) * e - z;
    } else {
      const double Va = V - w * L;
      r[0] = H / w * (std::asinh(V / H) - std::asinh(Va / H)) + H * L * e - x;
      r[1] = H / w * (std::sqrt(1 + V * V / (H * H)) - std::sqrt(1 + Va * Va / (H * H))) +
             (V * L - w * L * L / 2) * e - z;
    }
  };
  // The usual starting point, from the chord (lambda as in Peyrot and Goulois, 1979).
  const double chord2 = x * x + z * z;
  const double lambda = chord2 >= L * L ? 0.2 : std::sqrt(3 * ((L * L - z * z) / (x * x) - 1));
  double a = std::log(std::abs(w * x / (2 * lambda)));
  double b = std::log(w / 2 * (z / std::tanh(lambda) + L));
  if (grounded) b = std::min(b, std::log(0.9 * w * L));
  for (int it = 0; it < 200; ++it) {
    double r[2], ra[2], rb[2];
    const double H = std::exp(a), V = std::exp(b);
    residual(H, V, r);
    if (std::abs(r[0]) + std::abs(r[1]) < 1e-9 * (L + 1)) break;
    const double d = 1e-7;
    residual(H * std::exp(d), V, ra);
    residual(H, V * std::exp(d), rb);
    const double j00 = (ra[0] - r[0]) / d, j10 = (ra[1] - r[1]) / d, j01 = (rb[0] - r[0]) / d,
                 j11 = (rb[1] - r[1]) / d;
    const double det = j00 * j11 - j01 * j10;
    double da = -(j11 * r[0] - j01 * r[1]) / det, db = -(-j10 * r[0] + j00 * r[1]) / det;
    const double big = std::max(std::abs(da), std::abs(db));
    if (big > 0.5) da *= 0.5 / big, db *= 0.5 / big;  // damped: at most a factor e^0.5 a step
    a += da;
    b += db;
    if (grounded) b = std::min(b, std::log(w * L * (1 - 1e-12)));
  }
  const double H = std::exp(a), V = std::exp(b);
  double r[2];
  residual(H, V, r);
  if (std::abs(r[0]) + std::abs(r[1]) > 1e-6 * (L + 1)) return std::nan("");
  return std::hypot(H, V);
}

/// A line of the table and what it is compared with.
struct Line {
  std::string name;         // the table's label
  std::string file;         // lines/<file>.txt and lines/<file>.yaml
  double heave;             // m: the fairlead's heave amplitude, set on both sides (NaN: the config's motion)
  double duration;          // s simulated
  // The closed form's data: unstretched length [m], submerged weight [N/m], EA [N], fairlead x out and z up
  // from the lower end [m], a grounded part; for the payout (vertical), the load's submerged weight [N].
  double L, w, EA, x, z;
  bool grounded;
  double load_weight = 0.0;
  bool payout = false;
  double published_static = 0.0;  // kN: the published fairlead tension MoorDyn's test checks
  std::string series;             // under MoorDyn's tests/Mooring/: the reference's fairlead tension series
  double series_start = 10.0;     // s: the run's time at the series' t = 0 (and its window's start)
  std::string series_name = "OrcaFlex";
};

/// The submerged weight of a cylinder line [N/m].
double submergedWeight(double mass_per_length, double diameter, double g = 9.80665, double rho = 1025.0) {
  return (mass_per_length - rho * kPi * diameter * diameter / 4) * g;
}

/// The fairlead's prescribed motion (the project config's base.motion, a vertical sine): its height [m]
/// at t [s].
struct Heave {
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();  // m, world axes (z up)
  double period = 10.0;                                 // s
  double phase = 0.0;                                   // rad (the project's base.motion.phase)
  Eigen::Vector3d at(double t) const { return amplitude * std::sin(2 * kPi * t / period + phase); }
};

/// One side's run: the fairlead tension [N] every kSample s from t = 0 (static) and the wall time of
/// the stepping [s].
struct Run {
  std::vector<double> t, tension;
  double wall = 0.0, dt = 0.0;
  bool ok = true;
  std::string note;
};

/// The winch speed [m/s] the project's winch ran at, every kSample s: MoorDyn's line follows it.
struct Deployment {
  std::vector<double> speed;
};

/// MDB_VERBOSE=1 in the environment: MoorDyn's stdout not muted, and every run's tension series printed.
const bool kVerbose = std::getenv("MDB_VERBOSE") != nullptr;
// MDB_SEGMENT_TENSION=1: the project's fairlead tension is its first link's stretch's (the tension in the
// line's first segment, without the fairlead node's half link: what a lumped-mass code's first segment
// carries) instead of the force on the fairlead (base_force). A diagnostic of what the reported quantity
// is worth against the reference, whose convention the test data do not state (bench/README.md).
const bool kSegmentTension = std::getenv("MDB_SEGMENT_TENSION") != nullptr;

/// `per_step`: one MoorDyn_Step call per MoorDyn time step; otherwise one call per 0.1 s sample, as
/// MoorDyn's chain test drives it (MoorDyn then takes its steps within the call).
Run runMoorDyn(const std::string& file, const Heave& heave, double duration, const Deployment* deploy,
               bool per_step) {
  Run run;
  MoorDyn md;
  {
    MuteStdout mute(!kVerbose);
    md = MoorDyn_Create(file.c_str());
    if (md && !kVerbose) MoorDyn_SetVerbosity(md, MOORDYN_NO_OUTPUT);
  }
  if (!md) return run.ok = false, run.note = "MoorDyn_Create failed", run;
  unsigned int dof = 0;
  MoorDyn_NCoupledDOF(md, &dof);
  if (dof != 3) return MoorDyn_Close(md), run.ok = false, run.note = "expected one coupled point", run;
  MoorDynLine line = MoorDyn_GetLine(md, 1);
  // Initialized at rest, as MoorDyn's own test does: with the fairlead's velocity its internal damping
  // would put the velocity jump into the first tension read.
  // With a phase (MDB_REFERENCE_MOTION) the motion starts off zero: the run starts from its equilibrium
  // there, and the static tension (the first sample) is the one at zero heave, from an instance of its own.
  const Eigen::Vector3d start = heave.at(0.0);
  double x[3] = {start.x(), start.y(), start.z()}, xd[3] = {0, 0, 0}, f[3];
  int status;
  double still_force[3] = {0, 0, 0};
  bool still_known = false;
  {
    MuteStdout mute(!kVerbose);
    status = MoorDyn_Init(md, x, xd);  // its initial condition solve (dynamic relaxation): not timed
    if (status == MOORDYN_SUCCESS && !start.isZero()) {
      MoorDyn still = MoorDyn_Create(file.c_str());
      double zero[3] = {0, 0, 0}, rest[3] = {0, 0, 0};
      if (still && !kVerbose) MoorDyn_SetVerbosity(still, MOORDYN_NO_OUTPUT);
      if (still && MoorDyn_Init(still, zero, rest) == MOORDYN_SUCCESS) {
        MoorDyn_GetPointForce(MoorDyn_GetPoint(still, 2), still_force);
        still_known = true;
      }
      if (still) MoorDyn_Close(still);
      if (!still_known) status = MOORDYN_UNHANDLED_ERROR;
    }
  }
  if (status != MOORDYN_SUCCESS) return MoorDyn_Close(md), run.ok = false, run.note = "MoorDyn_Init failed", run;
  MoorDyn_GetDt(md, &run.dt);
  if (kVerbose) {
    const int one = 1;
    float fh, fv, ah, av;
    MoorDyn_GetFASTtens(md, &one, &fh, &fv, &ah, &av);
    double seg, pf[3];
    MoorDyn_GetLineFairTen(line, &seg);
    MoorDyn_GetPointForce(MoorDyn_GetPoint(md, 2), pf);
    std::printf("MoorDyn static: GetFASTtens %.6g N, GetLineFairTen %.6g N, GetPointForce %.6g N (%g %g %g)\n",
                std::hypot(fh, fv), seg, std::sqrt(pf[0] * pf[0] + pf[1] * pf[1] + pf[2] * pf[2]), pf[0], pf[1], pf[2]);
  }
  // The fairlead tension: the force the line puts on the vessel's point, as cable_dynamics' base_force.
  // Not MoorDyn_GetFASTtens: its vertical part takes the end node's mass with its added mass times g
  // off the node's net force instead of its submerged weight, which puts it above the force on the
  // vessel (+0.6 % on the payout, +6 % on the tether, +1.1 % on WD0050).
  MoorDynPoint vessel = MoorDyn_GetPoint(md, 2);  // point 2 is the vessel in every lines/*.txt
  auto norm = [](const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  run.t.push_back(0.0);
  MoorDyn_GetPointForce(vessel, f);  // at rest: the line's static pull [N]
  run.tension.push_back(norm(still_known ? still_force : f));
  // Driven as a coupled code drives it: each call gets the fairlead's position now and the secant
  // velocity to the call's end, so that its path is the sine's chord, continuous (a tangent velocity
  // would jump the position back a few mm every call). Per step, the chord is the step's; per 0.1 s
  // sample, the secant's velocity jumps every 0.1 s hit the stiff line (the jumper's dynamic error
  // 6.3 % -> 21 %, WD0050's 8.6 % -> 13 %).
  const int samples = int(std::lround(duration / kSample));
  double t = 0.0;
  for (int k = 0; k < samples && run.ok; ++k) {
    const double until = (k + 1) * kSample - 0.5 * run.dt;
    // The payout: the project winch's speed at this sample, as the line's unstretched length rate, which
    // MoorDyn integrates within its steps (MoorDyn_SetLineUnstretchedLength every 0.1 s as well made its
    // line diverge, NaN at 1.85 s).
    if (deploy && k < int(deploy->speed.size())) MoorDyn_SetLineUnstretchedLengthVel(line, deploy->speed[k]);
    const Clock::time_point start = Clock::now();
    while (t < until && run.ok) {
      double h = per_step ? run.dt : (k + 1) * kSample - t;  // s
      const Eigen::Vector3d now = heave.at(t), next = heave.at(t + h);
      for (int i = 0; i < 3; ++i) x[i] = now[i], xd[i] = (next[i] - now[i]) / h;
      run.ok = MoorDyn_Step(md, x, xd, f, &t, &h) == MOORDYN_SUCCESS;  // t advances by h
    }
    run.wall += std::chrono::duration<double>(Clock::now() - start).count();
    run.t.push_back(t);
    run.tension.push_back(norm(f));  // the force on the coupled point MoorDyn_Step returns [N]
  }
  if (!run.ok) run.note = "MoorDyn_Step failed";
  if (deploy) {  // where MoorDyn's integration of the payout rate ended
    double length;
    MoorDyn_GetLineUnstretchedLength(line, &length);
    char note[64];
    std::snprintf(note, sizeof note, "line ends at %.3f m", length);
    run.note += note;
  }
  MoorDyn_Close(md);
  return run;
}

/// The project's config `yaml` with `overrides` (key=value, as cable_sim's --set), for RK4 at its
/// recommended step (computed once into *rk4_dt) or the implicit integrator at `implicit_dt` [s].
CableParams projectParams(const std::string& yaml, std::vector<std::string> overrides, bool rk4, double* rk4_dt,
                          double implicit_dt = 0.01) {
  if (!rk4) {
    std::ostringstream dt;
    dt.precision(17);
    dt << "simulation.dt=" << implicit_dt;
    overrides.insert(overrides.end(), {"simulation.integrator=implicit", dt.str()});
    return cable_dynamics::loadConfigFile(yaml, overrides);
  }
  if (*rk4_dt <= 0) {  // the recommended RK4 step (half the stable limit), from a simulator built once
    std::vector<std::string> probe_overrides = overrides;
    probe_overrides.push_back("simulation.integrator=implicit");
    CableSimulator probe(cable_dynamics::loadConfigFile(yaml, probe_overrides));
    *rk4_dt = probe.estimateStableTimeStep();
  }
  std::ostringstream dt;
  dt.precision(17);
  dt << "simulation.dt=" << *rk4_dt;
  overrides.insert(overrides.end(), {"simulation.integrator=rk4", dt.str()});
  return cable_dynamics::loadConfigFile(yaml, overrides);
}

Run runProject(const CableParams& params, double duration, Deployment* record) {
  Run run;
  CableSimulator sim(params);  // with initial.mode equilibrium, the statics: not timed
  run.dt = sim.dt();
  cable_dynamics::SimulationSnapshot snap;
  auto fairlead = [&] {
    sim.snapshot(snap);
    if (record) {  // the deployment at this sample, for MoorDyn's line to follow
      record->speed.push_back(snap.winch_speed);
    }
    if (kSegmentTension && snap.chain.far_tension.size() > 0) return snap.chain.far_tension(0);  // N
    return sim.hasWinch() ? snap.line_pull : snap.chain.base_force.norm();  // N
  };
  run.t.push_back(0.0);
  run.tension.push_back(fairlead());
  {  // the static tension: the same equilibrium with the fairlead at rest (t = 0 has its heave velocity)
    CableParams still = params;
    still.base.motion.amplitude.setZero();
    CableSimulator at_rest(still);
    cable_dynamics::SimulationSnapshot rest;
    at_rest.snapshot(rest);
    run.tension[0] = at_rest.hasWinch() ? rest.line_pull : rest.chain.base_force.norm();
    if (kSegmentTension && rest.chain.far_tension.size() > 0) run.tension[0] = rest.chain.far_tension(0);
  }
  const int samples = int(std::lround(duration / kSample));
  for (int k = 0; k < samples && run.ok; ++k) {
    const double until = (k + 1) * kSample - 0.5 * run.dt;
    const Clock::time_point start = Clock::now();
    while (sim.time() < until && run.ok) {
      const cable_dynamics::StepReport report = sim.step();
      run.ok = report.ok;
      if (!report.ok) run.note = report.message;
    }
    run.wall += std::chrono::duration<double>(Clock::now() - start).count();
    run.t.push_back(sim.time());
    run.tension.push_back(fairlead());
  }
  if (sim.retriedSteps() > 0) run.note += std::to_string(sim.retriedSteps()) + " steps retried";
  return run;
}

/// The largest deviation of `run`'s fairlead tension from `reference`'s over the samples from `from` s on,
/// as a fraction of the reference's range there (max - min); infinite when either run failed.
double deviationFrom(const Run& run, const Run& reference, double from) {
  if (!run.ok || !reference.ok || run.tension.size() != reference.tension.size()) {
    return std::numeric_limits<double>::infinity();
  }
  double worst = 0.0, high = -1e300, low = 1e300;
  for (size_t i = 0; i < run.t.size(); ++i) {
    if (reference.t[i] < from - 1e-6) continue;
    worst = std::max(worst, std::abs(run.tension[i] - reference.tension[i]));
    high = std::max(high, reference.tension[i]);
    low = std::min(low, reference.tension[i]);
  }
  return worst / std::max(high - low, 1e-300);
}

/// The dynamic error against a reference series as MoorDyn's chain test computes it [-]: the largest
/// difference of the tension less its static value (the run's first sample; the reference's less
/// `static_reference` [N]), over twice the reference's largest such excursion. `series`: (t [s], T [N]).
double seriesError(const Run& r, const std::vector<std::pair<double, double>>& series, double static_reference) {
  double worst = 0, excursion = 0;
  const double t0 = r.tension.front();
  for (const auto& s : series) {
    const size_t i = std::min(r.t.size() - 1, size_t(std::lround(s.first / kSample)));
    const double ref = s.second - static_reference;
    worst = std::max(worst, std::abs((r.tension[i] - t0) - ref));
    excursion = std::max(excursion, std::abs(ref));
  }
  return worst / (2 * excursion);
}

/// The largest difference of `run`'s tension excursion (less its first sample, the statics) from `reference`'s at
/// the series' times, in seriesError's units (over twice the series' largest excursion from `static_reference`
/// [N]). By the triangle inequality seriesError(run) <= seriesError(reference) + this, whatever cancels:
/// a bound on a step's error against the series that does not lean on its error offsetting the model's.
double seriesDeviation(const Run& run, const Run& reference, const std::vector<std::pair<double, double>>& series,
                       double static_reference) {
  if (!run.ok || !reference.ok || run.tension.empty() || run.tension.size() != reference.tension.size()) {
    return std::numeric_limits<double>::infinity();
  }
  double worst = 0, excursion = 0;
  for (const auto& s : series) {
    const size_t i = std::min(run.t.size() - 1, size_t(std::lround(s.first / kSample)));
    worst = std::max(worst, std::abs((run.tension[i] - run.tension.front()) -
                                     (reference.tension[i] - reference.tension.front())));
    excursion = std::max(excursion, std::abs(s.second - static_reference));
  }
  return worst / (2 * excursion);
}

/// Each implicit step the ladder tried [s] and its seriesDeviation from the RK4 run (infinite where it failed).
using LadderDeviations = std::vector<std::pair<double, double>>;

/// The implicit integrator's step "as large as accuracy allows": the largest of kImplicitLadder [s] whose
/// fairlead tension stays within kStepTolerance of the range of the RK4 run `reference` (RK4 at its
/// recommended step, whose own time-step error is far below: fourth order at a fraction of the implicit
/// step) over the samples from `from` s on; 10 ms when none does. Each candidate's deviation goes to `note`.
constexpr double kImplicitLadder[] = {0.1, 0.05, 0.025, 0.02};  // s, divisors of kSample
constexpr double kStepTolerance = 0.01;                          // of the reference's tension range
/// Where `series` is not empty each candidate's error against it (seriesError, in brackets) goes to the
/// note too: the issue's own measure of a step's accuracy, beside the 1 % rule's.
double largestAccurateStep(const std::string& yaml, const std::vector<std::string>& overrides, double duration,
                           double from, const Run& reference, std::string& note,
                           const std::vector<std::pair<double, double>>& series = {}, double static_reference = 0.0,
                           LadderDeviations* ladder = nullptr) {
  double chosen = 0.0;  // s: the largest rung within kStepTolerance
  for (const double dt : kImplicitLadder) {
    double unused = 0.0;
    Run run;
    try {
      run = runProject(projectParams(yaml, overrides, false, &unused, dt), duration, nullptr);
    } catch (const std::exception& e) {
      run.ok = false;
      run.note = e.what();
    }
    const double deviation = deviationFrom(run, reference, from);
    char text[96];
    if (run.ok) {
      if (series.empty() || run.tension.empty()) {
        std::snprintf(text, sizeof text, "%s%g ms: %.2g%%", note.empty() ? "vs RK4: " : ", ", 1e3 * dt, 100 * deviation);
      } else {
        std::snprintf(text, sizeof text, "%s%g ms: %.2g%% (%.2f%%)", note.empty() ? "vs RK4 (vs the reference): " : ", ",
                      1e3 * dt, 100 * deviation, 100 * seriesError(run, series, static_reference));
      }
    } else {  // a step failed (diverged): said so, not a deviation
      std::snprintf(text, sizeof text, "%s%g ms: failed at %.3g s", note.empty() ? "vs RK4: " : ", ", 1e3 * dt,
                    run.t.empty() ? 0.0 : run.t.back());
    }
    note += text;
    const bool whole_ladder = ladder != nullptr && !series.empty();  // impl matched reads every rung's deviation
    if (whole_ladder) ladder->emplace_back(dt, seriesDeviation(run, reference, series, static_reference));
    if (deviation <= kStepTolerance && chosen == 0.0) chosen = dt;
    if (chosen > 0.0 && !whole_ladder) break;
  }
  return chosen > 0.0 ? chosen : 0.01;
}

/// A reference series of MoorDyn's tests: the fairlead tension [N] against the run's time [s] (`start` s
/// into the run at the file's t = 0), and where the file records it (the chains' OrcaFlex files:
/// tab-separated t, x, z, fairlead tension [kN], ...; their motion file starts at t = -10 s) the fairlead's
/// height [m] against the file's own t; the jumper's has t and top tension [kN] only. Empty when not found.
struct ReferenceSeries {
  std::vector<std::pair<double, double>> tension;  // (run's t [s], T [N])
  std::vector<std::pair<double, double>> height;   // (file's t [s], z [m])
};

ReferenceSeries readSeries(const std::string& path, double start) {
  ReferenceSeries series;
  std::ifstream in(path);
  for (std::string row; std::getline(in, row);) {
    std::replace(row.begin(), row.end(), ',', ' ');
    std::istringstream fields(row);
    std::vector<double> v;
    for (double value; fields >> value;) v.push_back(value);
    if (v.size() >= 4) {
      series.tension.push_back({v[0] + start, 1e3 * v[3]});
      series.height.push_back({v[0], v[2]});
    } else if (v.size() == 2) {
      series.tension.push_back({v[0] + start, 1e3 * v[1]});
    }
  }
  return series;
}

/// The lag [s] of a reference's own fairlead motion, `height` (readSeries), behind the sine the motion
/// file prescribes, A sin(2 pi t / period): OrcaFlex's chain files record a height A sin(2 pi (t - lag) /
/// period). From the fundamental's phase over the rows that span whole periods; 0 without such rows.
double referenceLag(const std::vector<std::pair<double, double>>& height, double period) {
  if (height.size() < 3) return 0.0;
  const double span = height.back().first - height.front().first;
  const double whole = period * std::floor(span / period + 1e-9);  // s: the whole periods the rows span
  if (whole <= 0.0) return 0.0;
  double s = 0.0, c = 0.0;  // z's projections on sin and cos of the fundamental
  const double w = 2 * kPi / period;
  for (const auto& [t, z] : height) {
    if (t - height.front().first >= whole - 1e-9) break;  // [t0, t0 + whole): the last row would count twice
    s += z * std::sin(w * t);
    c += z * std::cos(w * t);
  }
  return -std::atan2(c, s) / w;  // z = A sin(w t - w lag): s ~ cos(w lag), c ~ -sin(w lag)
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s <lines dir> [reps] [MoorDyn source dir]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  const int reps = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const std::string source = argc > 3 ? argv[3] : "";
  const double w_chain = submergedWeight(390.0, 0.252);
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Line> lines = {
      // MoorDyn's validation motions: ZZP1_A1 heaves 2 m, ZZP1_A2 5 m, both at a 10 s period.
      {"wd0050", "wd0050", 2.0, 30.0, 410.0, w_chain, 1.674e9, 400.0, 50.0, true, 0.0, false, 991.6, "QuasiStatic/WD0050_Chain_ZZP1_A1.txt"},
      {"wd0200", "wd0200", 2.0, 30.0, 760.0, w_chain, 1.674e9, 700.0, 200.0, true, 0.0, false, 2065.4, "QuasiStatic/WD0200_Chain_ZZP1_A1.txt"},
      {"wd0600", "wd0600", 2.0, 30.0, 1700.0, w_chain, 1.674e9, 1500.0, 600.0, true, 0.0, false, 5232.6, "QuasiStatic/WD0600_Chain_ZZP1_A1.txt"},
      {"wd0050a2", "wd0050", 5.0, 30.0, 410.0, w_chain, 1.674e9, 400.0, 50.0, true, 0.0, false, 991.6, "QuasiStatic/WD0050_Chain_ZZP1_A2.txt"},
      {"wd0200a2", "wd0200", 5.0, 30.0, 760.0, w_chain, 1.674e9, 700.0, 200.0, true, 0.0, false, 2065.4, "QuasiStatic/WD0200_Chain_ZZP1_A2.txt"},
      {"wd0600a2", "wd0600", 5.0, 30.0, 1700.0, w_chain, 1.674e9, 1500.0, 600.0, true, 0.0, false, 5232.6, "QuasiStatic/WD0600_Chain_ZZP1_A2.txt"},
      // Lowe and Langley's (2006) flexible jumper, case 1 (the top surging 10 m at 27 s; MoorDyn's test ramps
      // the motion in over a period, both sides here start the sine at once): its reference series, from
      // 27 s on, and the top tension MoorDyn's test checks at rest, |(11.40, 0, 45.71)| kN.
      {"jumper", "jumper", std::nan(""), 108.0, 170.0, submergedWeight(165.0, 0.396, 9.807, 1000.0), 500.0e6, 100.0,
       50.0, false, 0.0, false, 47.11, "lowe_and_langley_2006/Case 1.csv", 27.0, "Lowe-Langley"},
      {"tether", "tether", 0.5, 40.0, 100.0, submergedWeight(0.6, 0.025), 1.0e6, 40.0, 80.0, false},
      // The payout: vertical, the load's submerged weight (2000 kg - 1025 kg/m^3 x 0.8 m^3) x g; its
      // references are w L + W at 20 m (start) and at 50 m (end, static).
      {"payout", "payout", 0.0, 80.0, 50.0, submergedWeight(6.5, 0.04), 5.0e7, 0.0, 50.0, false,
       (2000.0 - 1025.0 * 0.8) * 9.80665, true},
  };

  std::printf("moordyn_bench: %d repetitions; wall time = stepping only, [ms per simulated s], median (min-max)\n",
              reps);
  std::printf("%-8s %-19s %8s %-24s %10s %-26s %-22s %-22s %s\n", "line", "side", "dt [ms]",
              "wall [ms/sim s]", "static [kN]", "static error [%]", "dyn. max/min [kN] (a)",
              "dynamic error [%]", "note");
  const char* only = std::getenv("MDB_ONLY");  // one line of the table, by name (debugging)
  const bool reference_motion = std::getenv("MDB_REFERENCE_MOTION") != nullptr;
  for (const Line& line : lines) {
    if (only && line.name != only) continue;
    const std::string yaml = dir + "/" + line.file + ".yaml", txt = dir + "/" + line.file + ".txt";
    char amplitude[64];
    std::snprintf(amplitude, sizeof amplitude, "base.motion.amplitude=[0, 0, %.17g]", line.heave);
    std::vector<std::string> project_overrides;  // the project's sides': the line's heave, then MDB_PROJECT_SET
    if (!std::isnan(line.heave)) project_overrides.push_back(amplitude);
    // MDB_PROJECT_SET: more overrides for the project's sides only (as cable_sim's --set, separated by
    // spaces), e.g. "cable.links=152": the project at another discretization than MoorDyn's.
    if (const char* extra = std::getenv("MDB_PROJECT_SET")) {
      std::istringstream words(extra);
      for (std::string word; words >> word;) project_overrides.push_back(word);
    }
    // The references.
    double ref_inext, ref_elastic, ref_end = 0.0;
    if (line.payout) {
      ref_inext = ref_elastic = line.w * 20.0 + line.load_weight;  // at the start, 20 m deployed
      ref_end = line.w * line.L + line.load_weight;                // at the end, 50 m
    } else {
      ref_inext = catenaryFairleadTension(line.L, line.w, inf, line.x, line.z, line.grounded);
      ref_elastic = catenaryFairleadTension(line.L, line.w, line.EA, line.x, line.z, line.grounded);
    }
    ReferenceSeries reference;  // the reference series (OrcaFlex's for the chains)
    if (!line.series.empty() && !source.empty())
      reference = readSeries(source + "/tests/Mooring/" + line.series, line.series_start);
    const std::vector<std::pair<double, double>>& orcaflex = reference.tension;
    // MDB_REFERENCE_MOTION=1: both sides' fairleads move as the reference's own did (its recorded height lags
    // the motion file's sine by `lag`: 0.0286 s on every chain file), not as MoorDyn's test drives them
    // (the motion file's sine, against the reference at the same times). The series' t = 0 is the run's
    // series_start, where the sine is at its zero: the run's sine is shifted by the lag.
    const CableParams config = cable_dynamics::loadConfigFile(yaml, project_overrides);
    Heave heave;
    heave.amplitude = config.base.motion.amplitude;
    heave.period = config.base.motion.period;
    heave.phase = config.base.motion.phase;
    double lag = 0.0;  // s
    if (reference_motion && !reference.height.empty() && !std::isnan(line.heave)) {
      lag = referenceLag(reference.height, heave.period);
      heave.phase = -2 * kPi * lag / heave.period;
      char phase[64];
      std::snprintf(phase, sizeof phase, "base.motion.phase=%.17g", heave.phase);
      project_overrides.push_back(phase);  // the same motion on the project's side
    }
    // The sides, run one after the other in each repetition.
    // The rigid RK4 side: the same config with EA and c_a 0 (the lines without EA skip it).
    const bool elastic = config.axial_stiffness > 0.0;
    std::vector<std::string> rigid_override = project_overrides;
    rigid_override.insert(rigid_override.end(), {"cable.axial_stiffness=0", "cable.axial_damping=0"});
    // The sides, in the table's order; kImplicitLarge: the implicit integrator at the largest step that keeps
    // the tension within 1 % of the RK4 run's range (largestAccurateStep), chosen in the first repetition.
    // kImplicitMatched (the lines with a reference series): the implicit integrator at the largest step of the
    // ladder whose error against the series is bounded by MoorDyn's: RK4's error plus the step's deviation from
    // RK4 (seriesDeviation, the triangle inequality) no larger than MoorDyn's RK2 error. The issue's own
    // accuracy measure, with no credit for an error that offsets the model's. It runs after MoorDyn's sides,
    // whose error it needs; the table prints it after impl large.
    enum Side { kRk4, kImplicit, kImplicitLarge, kImplicitMatched, kRk4Rigid, kMoorDynPerStep, kMoorDynSampled, kSides };
    const char* names[kSides] = {"cable_dyn RK4",       "cable_dyn impl", "cable_dyn impl large", "cable_dyn impl matched",
                                 "cable_dyn RK4 rigid", "MoorDyn RK2",    "MoorDyn 0.1s"};
    const Side run_order[kSides] = {kRk4,      kImplicit,       kImplicitLarge,  kRk4Rigid,
                                    kMoorDynPerStep, kMoorDynSampled, kImplicitMatched};
    LadderDeviations ladder;
    double matched_dt = 0.0;  // s; 0: no ladder step meets the bound (or no series)
    std::string matched_note;
    // Where the dynamic part starts (as the table's dynamic columns): OrcaFlex's window, the payout's whole
    // run, the tether after its first heave period.
    const double dynamic_from = !orcaflex.empty() ? line.series_start : line.payout ? 0.0 : heave.period;  // s
    double large_dt = 0.0;
    std::string large_note;
    std::vector<double> walls[kSides];
    Run first[kSides];
    double rk4_dt = 0.0, rk4_rigid_dt = 0.0;
    Deployment deploy;
    for (int rep = 0; rep < reps; ++rep) {
      for (const Side side : run_order) {
        if (side == kRk4Rigid && !elastic) continue;
        if (side == kImplicitMatched) {
          if (orcaflex.empty()) continue;
          if (rep == 0) {
            const double static_reference = 1e3 * line.published_static;
            const double rk4_error = seriesError(first[kRk4], orcaflex, static_reference);
            const double moordyn_error = first[kMoorDynPerStep].ok && !first[kMoorDynPerStep].tension.empty()
                                             ? seriesError(first[kMoorDynPerStep], orcaflex, static_reference)
                                             : 0.0;
            for (const auto& [dt, deviation] : ladder) {  // largest first
              if (rk4_error + deviation <= moordyn_error) {
                matched_dt = dt;
                char text[160];
                std::snprintf(text, sizeof text, "error bound: RK4's %.2f%% + %.2f%% from RK4 = %.2f%% <= MoorDyn's %.2f%%",
                              100 * rk4_error, 100 * deviation, 100 * (rk4_error + deviation), 100 * moordyn_error);
                matched_note = text;
                break;
              }
            }
          }
          if (matched_dt == 0.0) continue;
        }
        Run run;
        try {
          if (side == kRk4 || side == kImplicit)
            run = runProject(projectParams(yaml, project_overrides, side == kRk4, &rk4_dt), line.duration,
                             line.payout && side == kRk4 && rep == 0 ? &deploy : nullptr);
          else if (side == kImplicitLarge) {
            if (rep == 0)  // against this repetition's RK4 run, which ran just before
              large_dt = largestAccurateStep(yaml, project_overrides, line.duration, dynamic_from, first[kRk4], large_note,
                                             orcaflex, 1e3 * line.published_static, &ladder);
            double unused = 0.0;
            run = runProject(projectParams(yaml, project_overrides, false, &unused, large_dt), line.duration, nullptr);
            if (rep == 0) run.note = large_note + (run.note.empty() ? "" : "; " + run.note);
          } else if (side == kImplicitMatched) {
            double unused = 0.0;
            run = runProject(projectParams(yaml, project_overrides, false, &unused, matched_dt), line.duration, nullptr);
            if (rep == 0) run.note = matched_note + (run.note.empty() ? "" : "; " + run.note);
          } else if (side == kRk4Rigid)
            run = runProject(projectParams(yaml, rigid_override, true, &rk4_rigid_dt), line.duration, nullptr);
          else
            run = runMoorDyn(txt, heave, line.duration, line.payout ? &deploy : nullptr, side == kMoorDynPerStep);
        } catch (const std::exception& e) {
          run.ok = false;
          run.note = e.what();
        }
        walls[side].push_back(run.wall / line.duration);
        if (rep == 0) first[side] = run;
        if (rep == 0 && kVerbose) {
          std::printf("%s %s:", line.name.c_str(), names[side]);
          for (size_t i = 0; i < run.t.size(); i += 5) std::printf(" %.1f:%.5g", run.t[i], run.tension[i]);
          std::printf("\n");
        }
      }
    }
    // The table's rows.
    std::printf("%-8s reference: static fairlead tension %.4g kN inextensible, %.4g kN elastic (closed forms)",
                line.name.c_str(), ref_inext / 1e3, ref_elastic / 1e3);
    if (line.published_static > 0) std::printf(", %.1f kN published (MoorDyn's test)", line.published_static);
    if (line.payout) std::printf("; %.4g kN at 50 m (w L + W)", ref_end / 1e3);
    double o_max = 0, o_min = 0;
    if (!orcaflex.empty()) {
      o_max = -1e300, o_min = 1e300;
      for (const auto& s : orcaflex) o_max = std::max(o_max, s.second), o_min = std::min(o_min, s.second);
      std::printf("; %s dynamic %.1f / %.1f kN over t = %g-%g s", line.series_name.c_str(), o_max / 1e3, o_min / 1e3,
                  orcaflex.front().first, orcaflex.back().first);
      if (reference_motion) std::printf("; both fairleads %.4f s behind the motion file's sine, as the reference's", lag);
    }
    std::printf("\n");
    for (int side = 0; side < kSides; ++side) {
      if (side == kRk4Rigid && !elastic) continue;
      if (side == kImplicitMatched && orcaflex.empty()) continue;
      if (side == kImplicitMatched && matched_dt == 0.0) {
        std::printf("%-8s %-19s no step of the ladder within MoorDyn's error by the bound\n", line.name.c_str(),
                    names[side]);
        continue;
      }
      const Run& r = first[side];
      const auto mm = std::minmax_element(walls[side].begin(), walls[side].end());
      char wall[64], stat[96], dyn[64], err[64];
      std::snprintf(wall, sizeof wall, "%.3g (%.3g-%.3g)", 1e3 * median(walls[side]), 1e3 * *mm.first, 1e3 * *mm.second);
      if (r.tension.empty() || !r.ok) {
        std::printf("%-8s %-19s %8.3f %-24s FAILED: %s\n", line.name.c_str(), names[side], r.dt * 1e3, wall,
                    r.note.c_str());
        continue;
      }
      const double t0 = r.tension.front();
      if (line.published_static > 0)
        std::snprintf(stat, sizeof stat, "%+.1f inext %+.1f el %+.1f pub", 100 * (t0 / ref_inext - 1),
                      100 * (t0 / ref_elastic - 1), 100 * (t0 / (1e3 * line.published_static) - 1));
      else
        std::snprintf(stat, sizeof stat, "%+.1f inext %+.1f el", 100 * (t0 / ref_inext - 1), 100 * (t0 / ref_elastic - 1));
      // The dynamic part: over OrcaFlex's window where there is one (errors as MoorDyn's test computes
      // them: the largest difference of the tension less its static value, over twice the reference's
      // largest such excursion), the tether after its first heave period (the start from rest is a jolt),
      // the payout over the whole run (the winch starts at rest; its end against w L + W).
      const double from = dynamic_from;
      double d_max = -1e300, d_min = 1e300;
      for (size_t i = 0; i < r.t.size(); ++i)
        if (r.t[i] >= from - 1e-6) d_max = std::max(d_max, r.tension[i]), d_min = std::min(d_min, r.tension[i]);
      std::snprintf(dyn, sizeof dyn, "%.4g / %.4g", d_max / 1e3, d_min / 1e3);
      if (!orcaflex.empty()) {
        std::snprintf(err, sizeof err, "%.2f (vs %s)", 100 * seriesError(r, orcaflex, 1e3 * line.published_static),
                      line.series_name.c_str());
      } else if (line.payout) {
        // the last 5 s (the winch stopped at 65 s): their mean, an elastic line still bounces axially
        double sum = 0;
        int count = 0;
        for (size_t i = 0; i < r.t.size(); ++i)
          if (r.t[i] > line.duration - 5.0 + 1e-6) sum += r.tension[i], ++count;
        std::snprintf(err, sizeof err, "end %+.2f (vs w L + W)", 100 * (sum / count / ref_end - 1));
      } else {
        std::snprintf(err, sizeof err, "-");
      }
      std::printf("%-8s %-19s %8.3f %-24s %10.4g %-26s %-22s %-22s %s\n", line.name.c_str(), names[side], r.dt * 1e3,
                  wall, t0 / 1e3, stat, dyn, err, r.note.c_str());
    }
    if (line.payout) {  // MoorDyn's line created at the paid-out length: its static tension only
      MoorDyn md;
      double x[3] = {0, 0, 0}, xd[3] = {0, 0, 0};
      double f[3] = {0, 0, 0};
      {
        MuteStdout mute(!kVerbose);
        md = MoorDyn_Create((dir + "/payout50.txt").c_str());
        if (md && !kVerbose) MoorDyn_SetVerbosity(md, MOORDYN_NO_OUTPUT);
        if (md && MoorDyn_Init(md, x, xd) == MOORDYN_SUCCESS) MoorDyn_GetPointForce(MoorDyn_GetPoint(md, 2), f);
      }
      if (md) MoorDyn_Close(md);
      const double t = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
      std::printf("%-8s %-19s %8s %-24s %10.4g %+.2f vs w L + W at 50 m (lines/payout50.txt)\n", line.name.c_str(),
                  "MoorDyn 50 m", "-", "static only", t / 1e3, 100 * (t / ref_end - 1));
    }
    std::fflush(stdout);
  }
  std::printf(
      "Sides: cable_dynamics' RK4 at its recommended step and its implicit integrator at 10 ms with the line's EA\n"
      "  (impl large: at the largest of 100, 50, 25, 20 ms whose tension stays within 1 %% of the RK4 run's range\n"
      "  over the dynamic window, the note gives each candidate's deviation; 10 ms when none does; impl matched:\n"
      "  at the largest of them whose error against the reference series is at most MoorDyn's by a bound, RK4's\n"
      "  error plus the step's largest deviation from RK4 in the same units, which no cancellation can meet)\n"
      "  and axial damping as MoorDyn's (lines/*.yaml; the payout's winch pays out unstretched length), RK4\n"
      "  rigid at its recommended step with EA and c_a set to 0 (the inextensible links); MoorDyn (RK2, its\n"
      "  own step) called once per MoorDyn step (RK2 row: its errors are the ones to read) and once per 0.1 s as\n"
      "  its chain test calls it (0.1s row: less call overhead, velocity jumps every 0.1 s).\n"
      "static error: against the inextensible (inext) and the elastic (el) catenary, closed forms, and the published\n"
      "  value MoorDyn's tests check (pub: the chains' quasi-static codes, tests/quasi_static_chain.cpp; the\n"
      "  jumper's, tests/lowe_and_langley_2006.cpp). Rigid links sit on the inextensible form, elastic ones\n"
      "  (cable_dynamics with EA, MoorDyn) on the elastic one.\n"
      "(a) the chains over t = 10-30 s (OrcaFlex's window), the jumper over t = 27-107 s (Lowe and Langley's), the\n"
      "  tether after its first heave period, the payout over the whole run. dynamic error, the chains and the\n"
      "  jumper: max |(T - T_static) - (T_ref - T_pub)| over the window / (2 max |T_ref - T_pub|), as MoorDyn's\n"
      "  chain test computes it (its bound: 15 %%); the payout: the mean over the last 5 s against w L + W at 50 m.\n"
      "Tensions: the force of the line on the fairlead (cable_dynamics' base_force or line_pull, MoorDyn's force\n"
      "  on its coupled point), every 0.1 s.\n");
  return 0;
}
