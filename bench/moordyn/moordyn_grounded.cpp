// MoorDyn (lumped masses at the nodes) and cable_dynamics on the grounded elastic catenary of
// test/test_axial_elasticity.cpp (TheStaticsIsTheElasticCatenaryWithAGroundedPart), both against Irvine's
// closed form: a 100 m line, 8 kg/m, 0.05 m, EA 2e5 N, in water of 1025 kg/m^3 with g = 9.81 (submerged
// w = 58.74 N/m), from an anchor on a flat frictionless bed to a fairlead 20 m above it and 90 m out
// (89-91 m at n = 50). Statics only: MoorDyn's initial condition solve, the project's
// SimulatorUse::kStaticsOnly on the test's own config (groundedLine). MoorDyn is linked, never copied;
// its input files are written here, in the working directory (run.sh runs this in bench/moordyn/build/).
// Usage: moordyn_grounded (run.sh runs it after the table; MDB_ONLY=grounded runs it alone).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <moordyn/MoorDyn2.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "mute_stdout.h"
#include "reference/grounded_catenary.h"  // test/reference: the test's line and closed form

namespace {

// The test's line (test/reference/grounded_catenary.h) [m, N, kg/m, m, kg/m^3, m/s^2, N/m].
namespace line = cable_reference::grounded_line;
constexpr double kLength = line::kLength, kRise = line::kRise, kEA = line::kAxialStiffness;
constexpr double kMass = line::kMassPerLength, kDiameter = line::kDiameter, kRho = line::kWaterDensity, kG = line::kGravity;
const double kW = line::weight();  // submerged weight [N/m]
constexpr double kDepth = 50.0;  // m: MoorDyn's water depth, the anchor on its bed, the fairlead 30 m down
                                 // (off the free surface, where MoorDyn would take a node as half dry)

/// One side's statics: the fairlead tension and the anchor's horizontal pull [N], the suspended length
/// [m], and for MoorDyn how far from equilibrium its initial condition solve stopped.
struct Statics {
  bool ok = false;
  double fairlead = 0, anchor_h = 0, suspended = 0;
  double residual = 0;     // MoorDyn: max |net force| on an inner node over its weight w l [-]
  double h_spread = 0;     // MoorDyn: max - min of the segments' horizontal tension over H [-] (0 at rest)
  double penetration = 0;  // MoorDyn: deepest node below the bed [m]
  double wall = 0;         // s
};

/// MoorDyn on n equal segments, the bed stiffness kbot [Pa/m: N/m^2 of bed per m of depth and m of
/// diameter], its initial condition solver: `dynamic` false is 2.7.1's default (the "stationary" solve,
/// positions driven by the accelerations), true the older dynamic relaxation (ICgenDynamic 1, drag x5).
Statics runMoorDyn(int n, double span, double kbot, bool dynamic) {
  // The bed's damping: critical for a node bouncing on it (cBot d l v against 2 sqrt(k m), its mass with
  // the normal added mass, m + rho pi d^2/4 = 10.0 kg/m); without it the dynamic relaxation leaves the
  // grounded nodes ringing on the bed. Static results do not depend on it.
  const double m_a = kMass + kRho * M_PI * kDiameter * kDiameter / 4.0;  // kg/m
  const double cbot = 2.0 * std::sqrt(kbot * m_a / kDiameter);           // Pa s/m
  // dtM 0.5 ms: within the axial (0.0199 s period at n = 200) and the bed's (6.3 ms at kBot 2e8, n = 50)
  // periods. threshIC: the stationary solve stops when its acceleration sum falls 1e-10 below its start's
  // or changes by less than that over dtIC; the dynamic relaxation when the fairlead tension moves less
  // than 1e-8 over the last dtIC. Their true distance from equilibrium is measured below.
  const std::string file = "grounded_n" + std::to_string(n) + ".txt";
  FILE* f = std::fopen(file.c_str(), "w");
  if (!f) return {};
  std::fprintf(f,
               "--------------------- MoorDyn Input File ------------------------------------\n"
               "cable_dynamics bench: the grounded elastic catenary of test/test_axial_elasticity.cpp\n"
               "----------------------- LINE TYPES ------------------------------------------\n"
               "TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n"
               "(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n"
               "rope %g %g %g -1.0 0 1.2 1.0 0.0 0.0\n"
               "---------------------- POINT PROPERTIES --------------------------------\n"
               "ID Type X Y Z Mass Volume CdA Ca\n"
               "(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n"
               "1 Fixed 0 0 %.17g 0 0 0 0\n"
               "2 Vessel %.17g 0 %.17g 0 0 0 0\n"
               "---------------------- LINES ----------------------------------------\n"
               "ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs\n"
               "(#) (name) (#) (#) (m) (-) (-)\n"
               "1 rope 1 2 %g %d -\n"
               "---------------------- OPTIONS -----------------------------------------\n"
               "0 writeLog\n5e-4 dtM\n%g g\n%g WtrDnsty\n%g WtrDpth\n%g kBot\n%g cBot\n0 FrictionCoefficient\n"
               "%d ICgenDynamic\n1.0 dtIC\n%g TmaxIC\n%g threshIC\n1 disableOutput\n1 disableOutTime\n"
               "------------------------- need this line --------------------------------------\n",
               kDiameter, kMass, kEA, -kDepth, span, -kDepth + kRise, kLength, n, kG, kRho, kDepth, kbot, cbot,
               dynamic ? 1 : 0, dynamic ? 1000.0 : 500.0, dynamic ? 1e-8 : 1e-10);
  std::fclose(f);
  Statics out;
  MoorDyn md;
  {
    MuteStdout mute;
    md = MoorDyn_Create(file.c_str());
    if (md) MoorDyn_SetVerbosity(md, MOORDYN_NO_OUTPUT);
  }
  if (!md) return out;
  double x[3] = {span, 0.0, -kDepth + kRise}, xd[3] = {0.0, 0.0, 0.0};
  const auto start = std::chrono::steady_clock::now();
  int status;
  {
    MuteStdout mute;
    status = MoorDyn_Init(md, x, xd);
  }
  out.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != MOORDYN_SUCCESS) return MoorDyn_Close(md), out;
  MoorDynLine line = MoorDyn_GetLine(md, 1);
  // The fairlead: the force on the coupled point (the top segment's tension and the top node's weight, as
  // moordyn_bench reads it). The anchor is a fixed point, whose force MoorDyn does not sum: its H is the
  // first segment's horizontal tension (on a frictionless bed every segment carries the same H at rest).
  double pf[3], t[3], p[3], fn[3];
  MoorDyn_GetPointForce(MoorDyn_GetPoint(md, 2), pf);
  out.fairlead = std::sqrt(pf[0] * pf[0] + pf[1] * pf[1] + pf[2] * pf[2]);
  MoorDyn_GetLineNodeTen(line, 0, t);
  out.anchor_h = std::hypot(t[0], t[1]);
  double h_min = 1e300, h_max = 0.0;
  int first_off = -1;
  for (int i = 0; i <= n; ++i) {
    MoorDyn_GetLineNodeTen(line, i, t);
    MoorDyn_GetLineNodePos(line, i, p);
    h_min = std::min(h_min, std::hypot(t[0], t[1]));
    h_max = std::max(h_max, std::hypot(t[0], t[1]));
    if (first_off < 0 && p[2] > -kDepth) first_off = i;  // MoorDyn's contact: a node below the bed
    out.penetration = std::max(out.penetration, -kDepth - p[2]);
    if (i > 0 && i < n) {
      MoorDyn_GetLineNodeForce(line, i, fn);
      out.residual = std::max(out.residual, std::sqrt(fn[0] * fn[0] + fn[1] * fn[1] + fn[2] * fn[2]));
    }
  }
  out.residual /= kW * kLength / n;
  out.h_spread = (h_max - h_min) / out.anchor_h;
  out.suspended = kLength * (n - first_off) / n;  // unstretched arc from the first node off the bed up
  out.ok = first_off > 0;
  MoorDyn_Close(md);
  return out;
}

/// The project's statics on the test's groundedLine (equal links; its bed 1e6 N/m per m, 59 um deep).
Statics runProject(int n, double span) {
  const cable_dynamics::CableParams params =
      cable_dynamics::loadConfigString(line::projectConfig(std::vector<double>(n, kLength / n), span));
  Statics out;
  const auto start = std::chrono::steady_clock::now();
  cable_dynamics::CableSimulator sim(params, cable_dynamics::SimulatorUse::kStaticsOnly);
  out.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  cable_dynamics::SimulationSnapshot s;
  sim.snapshot(s);
  out.fairlead = s.chain.base_force.norm();
  out.anchor_h = s.chain.load_force.head<2>().norm();  // the anchor's horizontal pull, as the test reads it
  out.suspended = kLength - s.chain.seabed.grounded_length;
  out.ok = true;
  return out;
}

/// One row: the side's errors against the closed form `c` at `span`.
void row(const char* side, int n, double span, double kbot, const Statics& s, const cable_reference::GroundedCatenary& c) {
  if (!s.ok) {
    std::printf("%-15s %4d %6.1f %8.0e  FAILED\n", side, n, span, kbot);
    return;
  }
  std::printf("%-15s %4d %6.1f %8.0e %+9.3f %+9.3f %9.3f %8.3f", side, n, span, kbot,
              100 * (s.fairlead / std::hypot(c.horizontal, c.vertical) - 1), 100 * (s.anchor_h / c.horizontal - 1),
              s.suspended, c.vertical / kW);
  if (s.residual > 0 || s.h_spread > 0)
    std::printf(" %10.1e %10.1e %10.2g", s.residual, s.h_spread, 1e3 * s.penetration);
  else
    std::printf(" %10s %10s %10s", "-", "-", "-");
  std::printf(" %7.1f\n", s.wall);
  std::fflush(stdout);
}

}  // namespace

int main() {
  std::printf(
      "Grounded elastic catenary (test/test_axial_elasticity.cpp): 100 m, w = %.4f N/m, EA 2e5 N, rise 20 m;\n"
      "errors against Irvine's closed form; susp.: MoorDyn's arc from the first node off the bed to the\n"
      "fairlead, the project's 100 m less its grounded length, against V/w. resid.: MoorDyn's largest inner\n"
      "node net force over w l; H spread: (max - min) of its segments' horizontal tension over H.\n",
      kW);
  std::printf("%-15s %4s %6s %8s %9s %9s %9s %8s %10s %10s %10s %7s\n", "side", "n", "span", "kBot", "fair [%]",
              "anch H[%]", "susp. [m]", "V/w [m]", "resid.", "H spread", "pen. [mm]", "wall[s]");
  const double kbot = 2.0e7;  // Pa/m: kBot d = 1e6 N/m per m of line, the project's bed; 59 um deep
  const cable_reference::GroundedCatenary c90 = line::closedForm(90.0);
  for (int n : {25, 50, 100, 200}) {
    row("MoorDyn", n, 90.0, kbot, runMoorDyn(n, 90.0, kbot, false), c90);
    row("cable_dynamics", n, 90.0, 1e6 / kDiameter, runProject(n, 90.0), c90);
  }
  std::printf("-- spans at n = 50\n");
  for (double span : {89.0, 89.5, 90.5, 91.0}) {
    const cable_reference::GroundedCatenary c = line::closedForm(span);
    row("MoorDyn", 50, span, kbot, runMoorDyn(50, span, kbot, false), c);
    row("cable_dynamics", 50, span, 1e6 / kDiameter, runProject(50, span), c);
  }
  std::printf("-- MoorDyn's bed stiffness at n = 50, 90 m (penetration w / (kBot d))\n");
  for (double k : {2.0e5, 2.0e6, 2.0e8}) row("MoorDyn", 50, 90.0, k, runMoorDyn(50, 90.0, k, false), c90);
  // The older solver as a check on the default one (slow: n = 200 ran its 1000 s, 5 min on a loaded machine,
  // to within 2e-6 of the default's tensions).
  std::printf("-- MoorDyn's older dynamic relaxation (ICgenDynamic 1, threshIC 1e-8 over dtIC 1 s)\n");
  for (int n : {25, 50, 100}) row("MoorDyn dyn.rel", n, 90.0, kbot, runMoorDyn(n, 90.0, kbot, true), c90);
  return 0;
}
