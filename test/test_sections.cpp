// Sections and attachments (docs/MODEL.md section 9) against truths nobody here wrote: the exact force
// balance of a hanging cable (the tension at each point is the submerged weight below it), the jump in
// tension across a float or a clump weight (its net buoyancy or submerged weight), a lazy-wave shape
// against a shooting integration of the piecewise catenary written here, the energy balance of a
// swinging two-section cable with a float, and the Morison drag of a section of another diameter.
#include <cmath>
#include <iomanip>
#include <iostream>

#include <gtest/gtest.h>

#include <Eigen/LU>

#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/stable_step.h"
#include "cable_dynamics/statics/static_solver.h"

using namespace cable_dynamics;

namespace {

constexpr double kRho = 1025.0;  // [kg/m^3]
constexpr double kG = 9.81;      // [m/s^2]

/// Submerged weight per metre of a section of diameter d [m] and mass per length m [kg/m] [N/m].
double weightPerLength(double d, double m, double rho = kRho) { return kG * (m - rho * M_PI * 0.25 * d * d); }

/// A 40 m cable of 20 links hanging in still water: 20 m of heavy armoured cable (d 0.05 m, 4 kg/m) at
/// the base, 20 m of light cable (d 0.03 m, 0.8 kg/m) below, and a 20 kg load of 0.005 m^3.
const char* const kTwoSections =
    "cable: {links: 20, length: 40.0, diameter: 0.03, mass_per_length: 0.8,\n"
    "        sections: [{length: 20.0, diameter: 0.05, mass_per_length: 4.0}, {diameter: 0.03}]}\n"
    "load: {mass: 20.0, volume: 0.005}\n"
    "simulation: {dt: 0.001}\n";

/// The submerged weight below arc length s of kTwoSections plus its load, and `points` (arc length,
/// submerged weight [N]) [N].
double weightBelow(double s, const std::vector<std::pair<double, double>>& points = {}) {
  const double w1 = weightPerLength(0.05, 4.0), w2 = weightPerLength(0.03, 0.8);
  double below = w1 * std::max(20.0 - s, 0.0) + w2 * std::min(40.0 - s, 20.0) + kG * (20.0 - kRho * 0.005);
  for (const auto& p : points) below += p.first >= s ? p.second : 0.0;
  return below;
}

StaticSolution solveFree(ChainDynamics& chain) {
  StaticProblem problem;
  const StaticSolution s = solveStatics(chain.model(), chain.deployed(), chain.current(), problem);
  EXPECT_TRUE(s.converged) << s.message;
  return s;
}

/// The state of a solved shape at rest, the accumulators zero.
Eigen::VectorXd restState(const StaticSolution& s) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(StateLayout::size(static_cast<int>(s.twists.size())));
  setRestState(s, x);
  return x;
}

}  // namespace

TEST(Sections, LinksTakeTheSectionTheirCentreLiesIn) {
  const CableParams p = loadConfigString(kTwoSections);
  ASSERT_EQ(p.sections.size(), 2u);
  EXPECT_DOUBLE_EQ(p.sections[1].length, 20.0);  // the last one runs to the tip
  const LinkProperties props = deriveLinkProperties(p);
  for (int k = 0; k < 20; ++k) {
    const bool upper = k < 10;
    EXPECT_EQ(props.section(k), upper ? 0 : 1);
    EXPECT_DOUBLE_EQ(props.radius(k), upper ? 0.025 : 0.015);
    EXPECT_NEAR(props.mass(k), (upper ? 4.0 : 0.8) * 2.0, 1e-12);
  }
  // A link across a boundary goes by its centre: boundary at 20.9 m, links of 2 m, so link 11 (20..22 m,
  // centre 21 m) is in the second section, link 10 (18..20 m) in the first.
  const CableParams shifted = loadConfigString(
      "cable: {links: 20, length: 40.0, diameter: 0.03, mass_per_length: 0.8,\n"
      "        sections: [{length: 20.9, mass_per_length: 4.0}, {length: 19.1}]}\n");
  const LinkProperties r = deriveLinkProperties(shifted);
  EXPECT_EQ(r.section(9), 0);
  EXPECT_EQ(r.section(10), 1);  // 20..22 m, centre 21 m > 20.9 m: the second section
}

TEST(Sections, ConfigErrorsNameTheKeyTheValueAndTheRange) {
  const auto message = [](const std::string& yaml) -> std::string {
    try {
      loadConfigString(yaml);
    } catch (const ConfigError& e) {
      return std::string(e.key()) + " | " + e.what();
    }
    return "(accepted)";
  };
  const std::string base = "cable: {links: 4, length: 10.0, diameter: 0.03, mass_per_length: 0.8, sections: ";
  std::string m = message(base + "[{length: 4.0}, {length: 5.0}]}\n");
  EXPECT_NE(m.find("cable.sections[1].length"), std::string::npos) << m;
  EXPECT_NE(m.find("adding up"), std::string::npos) << m;
  m = message(base + "[{length: 12.0}, {}]}\n");
  EXPECT_NE(m.find("cable.sections[0].length"), std::string::npos) << m;
  m = message(base + "[{length: 4.0, diameter: -1.0}, {}]}\n");
  EXPECT_NE(m.find("cable.sections[0].diameter"), std::string::npos) << m;
  m = message(base + "[{length: 4.0, colour: red}, {}]}\n");
  EXPECT_NE(m.find("colour"), std::string::npos) << m;
  m = message(base + "[{length: 4.0, mass_per_length: 1.0, material_density: 900.0}, {}]}\n");
  EXPECT_NE(m.find("cable.sections[0].mass_per_length"), std::string::npos) << m;
  m = message(base + "[{}]}\n");
  EXPECT_EQ(m, "(accepted)");  // one section, the whole cable
  m = message(base + "[]}\n");
  EXPECT_NE(m.find("cable.sections"), std::string::npos) << m;
  const std::string cable = "cable: {links: 4, length: 10.0, diameter: 0.03, mass_per_length: 0.8}\n";
  m = message(cable + "attachments: [{arc_length: 11.0, mass: 1.0}]\n");
  EXPECT_NE(m.find("attachments[0].arc_length"), std::string::npos) << m;
  m = message(cable + "attachments: [{mass: 1.0}]\n");
  EXPECT_NE(m.find("attachments[0].arc_length"), std::string::npos) << m;
  m = message(cable + "attachments: [{arc_length: 5.0, volume: -1.0}]\n");
  EXPECT_NE(m.find("attachments[0].volume"), std::string::npos) << m;
  m = message(cable + "attachments: [{arc_length: 5.0, mass: 1.0}]\nwinch: {max_length: 20.0}\n");
  EXPECT_NE(m.find("attachments"), std::string::npos) << m;
  // A section's material density over its own diameter.
  const CableParams p = loadConfigString(
      "cable: {links: 4, length: 10.0, diameter: 0.03, material_density: 1000.0, sections: [{length: 5.0, diameter: 0.06}, {}]}\n");
  EXPECT_NEAR(p.sections[0].mass_per_length, 1000.0 * M_PI * 0.03 * 0.03, 1e-12);
  EXPECT_NEAR(p.sections[1].mass_per_length, 1000.0 * M_PI * 0.015 * 0.015, 1e-12);
}

// Hanging straight down in still water, the tension at every point is the submerged weight below it:
// the statics and, after the swing of a released cable has died out under the elevation dampers, the
// dynamics.
TEST(Sections, TwoSectionHangingCableCarriesTheWeightBelowIt) {
  {
    ChainDynamics chain(loadConfigString(kTwoSections));
    const StaticSolution s = solveFree(chain);
    double worst = 0.0;
    for (int k = 0; k < 20; ++k) worst = std::max(worst, std::abs(s.tension(k) / weightBelow(2.0 * k) - 1.0));
    std::cout << "statics: tension against the weight below, worst " << worst << " relative; top " << s.tension(0)
              << " N (exact " << weightBelow(0.0) << ")\n";
    EXPECT_LT(worst, 1e-9);
  }
  CableSimulator sim(loadConfigString(kTwoSections, {"initial.elevation=0.3", "cable.damping.elevation=200.0"}));
  for (int i = 0; i < 60000; ++i) ASSERT_TRUE(sim.step().ok);
  SimulationSnapshot snap;
  sim.snapshot(snap);
  double worst = 0.0;
  for (int k = 0; k < 20; ++k) worst = std::max(worst, std::abs(snap.chain.tension(k) / weightBelow(2.0 * k) - 1.0));
  std::cout << "dynamics after 60 s: worst " << worst << " relative, kinetic energy " << snap.chain.kinetic_energy
            << " J\n";
  EXPECT_LT(worst, 1e-6);
}

// A clump weight on a node and one inside a link: the tension below and above differ by the link's own
// weight plus the clump's submerged weight.
TEST(Sections, ClumpWeightAddsItsSubmergedWeightToTheTension) {
  const double clump = kG * (50.0 - kRho * 0.01), small = kG * (12.0 - kRho * 0.002);
  ChainDynamics chain(loadConfigString(std::string(kTwoSections) +
                                       "attachments: [{arc_length: 30.0, mass: 50.0, volume: 0.01, drag_area: 0.2},\n"
                                       "              {arc_length: 35.3, mass: 12.0, volume: 0.002}]\n"));
  const StaticSolution s = solveFree(chain);
  const std::vector<std::pair<double, double>> points = {{30.0, clump}, {35.3, small}};
  double worst = 0.0;
  for (int k = 0; k < 20; ++k) worst = std::max(worst, std::abs(s.tension(k) / weightBelow(2.0 * k, points) - 1.0));
  const double w2 = weightPerLength(0.03, 0.8) * 2.0;  // one link of the light section [N]
  const double jump = s.tension(15) - s.tension(16) - w2, jump_inside = s.tension(17) - s.tension(18) - w2;
  std::cout << "clump: jump " << jump << " N (submerged weight " << clump << "), inside a link " << jump_inside
            << " N (" << small << "); tension profile worst " << worst << "\n";
  EXPECT_NEAR(jump, clump, 1e-9 * clump);
  EXPECT_NEAR(jump_inside, small, 1e-9 * clump);
  EXPECT_LT(worst, 1e-9);
  // The dynamics at the solved shape: at rest, with the same tensions.
  ChainOutputs out;
  ASSERT_TRUE(chain.evaluate(restState(s), EndInputs(), out));
  EXPECT_LT(out.omega_rate.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(out.tension(15) - out.tension(16) - w2, clump, 1e-8 * clump);
}

namespace {

/// The piecewise catenary of a limp cable (x horizontal, z down) from the base at the origin to a tip
/// pulled by the anchor with force `tip` (x, z) [N]: the force on the part beyond s is
/// G(s) = tip + (integral of w from s to L) e_z + sum of the point loads beyond s, the cable lies along
/// G / |G| with tension |G|. Weight per length w(s) by `segments` (start arc length, w [N/m]); point
/// loads (arc length, + down [N]) on the part beyond them. Positions at arc lengths `at` by Simpson's
/// rule between the kinks.
struct Catenary2d {
  std::vector<std::pair<double, double>> segments;  // (start, w), the first at 0
  std::vector<std::pair<double, double>> points;    // (arc length, vertical force + down)
  double length = 0.0;

  Eigen::Vector2d outboardForce(double s, const Eigen::Vector2d& tip) const {
    double vertical = 0.0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const double a = segments[i].first, b = i + 1 < segments.size() ? segments[i + 1].first : length;
      vertical += segments[i].second * std::max(0.0, b - std::max(a, s));
    }
    for (const auto& p : points) vertical += p.first >= s ? p.second : 0.0;
    return tip + Eigen::Vector2d(0.0, vertical);
  }

  /// Positions at the sorted arc lengths `at`.
  std::vector<Eigen::Vector2d> positions(const Eigen::Vector2d& tip, const std::vector<double>& at) const {
    std::vector<double> kinks;
    for (const auto& seg : segments) kinks.push_back(seg.first);
    for (const auto& p : points) kinks.push_back(p.first);
    kinks.push_back(length);
    std::vector<Eigen::Vector2d> out;
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    double s = 0.0;
    const auto direction = [&](double arc, double side) {
      // Just inside [arc, ...) (side +1) or (..., arc] (side -1): the point loads are jumps.
      const Eigen::Vector2d g = outboardForce(arc + side * 1e-12, tip);
      return Eigen::Vector2d(g / g.norm());
    };
    for (double target : at) {
      while (s < target) {
        double next = target;
        for (double k : kinks) {
          if (k > s + 1e-12 && k < next) next = k;
        }
        const int cells = 400;
        const double h = (next - s) / cells;
        Eigen::Vector2d sum = direction(s, 1.0) + direction(next, -1.0);
        for (int i = 1; i < cells; ++i) sum += (i % 2 ? 4.0 : 2.0) * direction(s + i * h, 1.0);
        x += (h / 3.0) * sum;
        s = next;
      }
      out.push_back(x);
    }
    return out;
  }

  /// The anchor's pull that puts the tip at `tip_position`: Newton on (F_x, F_z) with differenced columns.
  Eigen::Vector2d shoot(const Eigen::Vector2d& tip_position, Eigen::Vector2d force) const {
    for (int it = 0; it < 50; ++it) {
      const Eigen::Vector2d miss = positions(force, {length}).back() - tip_position;
      if (miss.norm() < 1e-11 * length) break;
      Eigen::Matrix2d jacobian;
      for (int c = 0; c < 2; ++c) {
        Eigen::Vector2d d = Eigen::Vector2d::Zero();
        d(c) = 1e-6 * force.norm();
        jacobian.col(c) = (positions(force + d, {length}).back() - positions(force - d, {length}).back()) / (2.0 * d(c));
      }
      force -= jacobian.inverse() * miss;
    }
    return force;
  }
};

/// A 100 m riser of 100 links from the base to an anchor 60 m across and 50 m down, with five floats
/// from 45 m to 65 m: a lazy wave. Heavy cable (d 0.05 m, 3 kg/m in air) with a lighter stretch of
/// 0.04 m in diameter from 40 m to 70 m.
std::string lazyWave(double float_mass, double float_volume) {
  std::string floats = "attachments: [";
  for (int i = 0; i < 5; ++i) {
    floats += std::string(i ? ", " : "") + "{arc_length: " + std::to_string(45.0 + 5.0 * i) +
              ", mass: " + std::to_string(float_mass) + ", volume: " + std::to_string(float_volume) + "}";
  }
  floats += "]\n";
  return "cable: {links: 100, length: 100.0, diameter: 0.05, mass_per_length: 3.0,\n"
         "        sections: [{length: 40.0}, {length: 30.0, diameter: 0.04, mass_per_length: 2.0}, {}]}\n"
         "load: {mass: 0.0, mode: anchored}\n" +
         floats;
}

}  // namespace

// The lazy wave: the statics against the shooting integration of the piecewise catenary above (the base
// tension, the anchor's pull, every node), and across each float the tension jumps by its net buoyancy.
TEST(Attachments, LazyWaveMatchesThePiecewiseCatenaryAndFloatsLiftByTheirBuoyancy) {
  const double float_mass = 10.0, float_volume = 0.025;  // net buoyancy (0.025 rho - 10) g = 153 N each
  const double buoyancy = kG * (kRho * float_volume - float_mass);
  ChainDynamics chain(loadConfigString(lazyWave(float_mass, float_volume)));
  StaticProblem problem;
  problem.tip_coupled = true;
  problem.target_position = Eigen::Vector3d(60.0, 0.0, 50.0);
  const StaticSolution s = solveStatics(chain.model(), chain.deployed(), chain.current(), problem);
  std::cout << "lazy wave statics: converged " << s.converged << " in " << s.iterations << " iterations, residual "
            << s.residual << " " << s.message << "\n";
  ASSERT_TRUE(s.converged) << s.message;

  // The jumps across the floats: J_{k+1} - J_k = the link's weight + the float's (0, 0, -B) (J_k: the force
  // on everything outboard of link k's base end).
  const double w_light = weightPerLength(0.04, 2.0), w_heavy = weightPerLength(0.05, 3.0);
  double worst_jump = 0.0;
  for (int i = 0; i < 5; ++i) {
    const int k = 45 + 5 * i;  // the float sits on link k's base end
    const Eigen::Vector3d jump = s.joint_force.col(k + 1) - s.joint_force.col(k) - Eigen::Vector3d(0.0, 0.0, w_light);
    worst_jump = std::max(worst_jump, (jump - Eigen::Vector3d(0.0, 0.0, -buoyancy)).norm() / buoyancy);
  }
  std::cout << "float jumps off their buoyancy " << buoyancy << " N by at most " << worst_jump << " relative\n";
  EXPECT_LT(worst_jump, 1e-8);

  // The shooting reference, to the solver's own tip (the anchor spring stretches by ~1e-4 m).
  Catenary2d reference;
  reference.length = 100.0;
  reference.segments = {{0.0, w_heavy}, {40.0, w_light}, {70.0, w_heavy}};
  for (int i = 0; i < 5; ++i) reference.points.push_back({45.0 + 5.0 * i, -buoyancy});
  const Eigen::Vector3d anchor_pull = s.hold_force;  // the exact anchor's force on the tip [N]
  const Eigen::Vector2d tip(s.tip_position.x(), s.tip_position.z());
  const Eigen::Vector2d pull = reference.shoot(tip, Eigen::Vector2d(anchor_pull.x(), anchor_pull.z()));
  std::vector<double> arcs;
  for (int k = 1; k <= 100; ++k) arcs.push_back(k);
  const std::vector<Eigen::Vector2d> nodes = reference.positions(pull, arcs);
  Eigen::Vector3d node = Eigen::Vector3d::Zero();
  double worst_node = 0.0, hump = 1e9, hump_reference = 1e9, sag = 0.0, sag_reference = 0.0;
  for (int k = 0; k < 100; ++k) {
    node += s.axes.col(k);
    worst_node = std::max(worst_node, (Eigen::Vector2d(node.x(), node.z()) - nodes[k]).norm());
    if (k >= 40 && k < 75) {
      hump = std::min(hump, node.z());  // the shallowest point of the arch
      hump_reference = std::min(hump_reference, nodes[k].y());
    }
    if (k < 45) {
      sag = std::max(sag, node.z());
      sag_reference = std::max(sag_reference, nodes[k].y());
    }
  }
  const Eigen::Vector2d base_reference = reference.outboardForce(0.0, pull);  // G(0) = -J_0
  const Eigen::Vector2d base(-s.joint_force(0, 0), -s.joint_force(2, 0));
  const double base_error = (base - base_reference).norm() / base_reference.norm();
  const double pull_error = (Eigen::Vector2d(anchor_pull.x(), anchor_pull.z()) - pull).norm() / pull.norm();
  std::cout << std::setprecision(7) << "lazy wave: base tension " << base.norm() << " N (reference " << base_reference.norm()
            << ", error " << 100 * base_error << " %), anchor pull " << anchor_pull.norm() << " N (reference "
            << pull.norm() << ", error " << 100 * pull_error << " %), nodes within " << worst_node
            << " m; sag bottom " << sag << " m (" << sag_reference << "), hump top " << hump << " m (" << hump_reference
            << ")\n";
  // The chain of 100 one-metre links against the continuous shooting reference: the gap is the chain's
  // discretization (second order in the link length), not the solvers' (1e-9). Measured: base tension
  // 0.0038 %, anchor pull 0.0059 %, nodes within 2.9 mm, sag bottom 0.016 %, hump top 0.028 %; the bounds
  // sit about 5x above.
  EXPECT_LT(base_error, 2e-4);
  EXPECT_LT(pull_error, 3e-4);
  EXPECT_LT(worst_node, 0.015);  // [m]
  EXPECT_NEAR(hump, hump_reference, 1.5e-3 * std::abs(hump_reference));
  EXPECT_NEAR(sag, sag_reference, 1e-3 * std::abs(sag_reference));
  EXPECT_LT(hump, sag - 5.0);  // a hump: the arch rises well above the sag before it

  // The dynamics at the solved shape stay at rest.
  EndInputs ends;
  ends.load_coupled = true;
  ends.target_position = s.tip_position;  // the exact hold judged where the statics put the tip (test_statics)
  Eigen::VectorXd rate(chain.stateSize());
  ASSERT_TRUE(chain.derivative(restState(s), ends, rate));
  double worst_rate = 0.0;
  for (int k = 0; k < 100; ++k) worst_rate = std::max(worst_rate, rate.segment<3>(StateLayout::omega(k)).norm());
  std::cout << "angular accelerations at the solved shape: " << worst_rate << " rad/s^2\n";
  EXPECT_LT(worst_rate, 1e-6 * kG);  // g / l at the statics' 1e-9 residual (test_statics alike)
}

namespace {

/// A 10 m cable of 10 links: 5 m of heavy cable, 5 m of light, a float mid-link at 7.3 m and a small load,
/// swinging in 3-D from a tilt.
CableParams swinging(double density, bool drag, Formulation formulation = Formulation::kRecursive) {
  const std::string coefficients = drag ? "" : ", drag_normal: 0.0, drag_tangential: 0.0";
  CableParams p = loadConfigString(
      "cable: {links: 10, length: 10.0, diameter: 0.03, mass_per_length: 1.5,\n"
      "        sections: [{length: 5.0, diameter: 0.05, mass_per_length: 5.0" + coefficients + "},\n"
      "                   {diameter: 0.02, mass_per_length: 0.5, added_mass: 0.8" + coefficients + "}]}\n"
      "attachments: [{arc_length: 7.3, mass: 2.0, volume: 0.006, added_mass: 3.0, drag_area: " +
      std::string(drag ? "0.05" : "0.0") + "}]\n"
      "load: {mass: 3.0, volume: 0.001, added_mass: 1.0}\n"
      "initial: {elevation: [0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.2, 1.2, 1.2], azimuth: [0.0, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1]}\n"
      "simulation: {dt: 0.0005}\n",
      {"fluid.density=" + std::to_string(density)});
  p.simulation.formulation = formulation;
  return p;
}

}  // namespace

// Kinetic + potential + dissipated - work stays put over 60 s: the attachment's weight, buoyancy and mass
// in the energies, its drag and added mass in the dissipated power.
TEST(Attachments, EnergyBalanceOfASwingingTwoSectionCableWithAFloat) {
  struct Case {
    const char* name;
    double density;
    bool drag;
  };
  for (const Case c : {Case{"air", 0.0, false}, Case{"water, no drag", kRho, false}, Case{"water, drag", kRho, true}}) {
    CableSimulator sim(swinging(c.density, c.drag));
    SimulationSnapshot snap;
    sim.snapshot(snap);
    const double start = snap.total_energy;
    double scale = 0.0, worst = 0.0;
    for (int i = 0; i < 120000; ++i) {
      ASSERT_TRUE(sim.step().ok) << c.name << " at " << sim.time();
      if (i % 200 != 0) continue;
      sim.snapshot(snap);
      scale = std::max(scale, std::abs(snap.chain.kinetic_energy) + std::abs(snap.chain.potential_energy));
      worst = std::max(worst, std::abs(snap.total_energy - start));
    }
    std::cout << c.name << ": balance moved by " << worst << " J of " << scale << " J (" << worst / scale
              << "), dissipated " << snap.dissipated_energy << " J\n";
    // RK4 at 0.5 ms over 60 s: measured 1.0e-8 of the scale in air, 3.3e-9 in water without drag, 1.5e-14
    // with drag (which damps the swing); 5e-8 is 5x the largest.
    EXPECT_LT(worst, 5e-8 * scale) << c.name;
    EXPECT_EQ(sim.retriedSteps(), 0);
    if (c.drag) {
      EXPECT_GT(snap.dissipated_energy, 0.01 * scale);
    }
  }
}

// The O(n) recursion and the dense mass matrix agree with sections and an attachment with added mass.
TEST(Attachments, RecursionAndDenseMassMatrixAgree) {
  ChainDynamics recursive(swinging(kRho, true)), dense(swinging(kRho, true, Formulation::kPaper));
  CableSimulator sim(swinging(kRho, true));
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(sim.step().ok);  // a moving state
  const Eigen::VectorXd x = sim.state();
  Eigen::VectorXd a(x.size()), b(x.size());
  EndInputs ends;
  ASSERT_TRUE(recursive.derivative(x, ends, a));
  ASSERT_TRUE(dense.derivative(x, ends, b));
  const double difference = (a - b).cwiseAbs().maxCoeff() / a.cwiseAbs().maxCoeff();
  std::cout << "recursive against dense: " << difference << " relative\n";
  EXPECT_LT(difference, 1e-9);
}

// The Morison drag of each section at its own diameter and coefficients: every link straight along one
// axis at rest in a uniform current, so the relative velocity is the same all along it and the drag
// per metre is 1/2 rho (C_n d |v_n| v_n + C_t pi d |v_t| v_t) exactly; also through the depth-profile path.
TEST(Sections, DragOfASectionOfAnotherDiameterIsMorisons) {
  const std::string cable =
      "cable: {links: 8, length: 16.0, diameter: 0.03, mass_per_length: 1.0,\n"
      "        sections: [{length: 6.0, diameter: 0.08, drag_normal: 1.5, drag_tangential: 0.02}, {}]}\n";
  for (const bool profile : {false, true}) {
    const std::string fluid = profile ? "fluid: {drag_normal: 1.1, drag_tangential: 0.008, current_profile: [[0.0, 0.8, 0.3, 0.0], [100.0, 0.8, 0.3, 0.0]]}\n"
                                      : "fluid: {drag_normal: 1.1, drag_tangential: 0.008, current: [0.8, 0.3, 0.0]}\n";
    ChainDynamics chain(loadConfigString(cable + fluid));
    const Eigen::Vector3d axis = Eigen::Vector3d(0.5, 0.2, 0.7).normalized();  // paper frame
    Eigen::VectorXd x = Eigen::VectorXd::Zero(chain.stateSize());
    for (int k = 0; k < 8; ++k) x.segment<3>(StateLayout::axis(k)) = axis;
    ChainOutputs out;
    ASSERT_TRUE(chain.evaluate(x, EndInputs(), out));
    const Eigen::Vector3d current(0.8, -0.3, 0.0);  // world (0.8, 0.3, 0) in the paper frame (y and z flip)
    double worst = 0.0;
    for (int k = 0; k < 8; ++k) {
      const bool first = k < 3;  // centres at 1, 3, 5 m: the first section
      const double d = first ? 0.08 : 0.03, cn = first ? 1.5 : 1.1, ct = first ? 0.02 : 0.008, l = 2.0;
      const Eigen::Vector3d vt = current.dot(axis) * axis, vn = current - vt;
      const Eigen::Vector3d expected = l * 0.5 * kRho * d * (cn * vn.norm() * vn + ct * M_PI * vt.norm() * vt);
      const Eigen::Vector3d weight(0.0, 0.0, l * weightPerLength(d, 1.0));
      const Eigen::Vector3d drag = chain.data().links.get(&LinkBlock::force, k) - weight;
      worst = std::max(worst, (drag - expected).norm() / expected.norm());
      // Uniform along the link: its first moment is l/2 times the force.
      const Eigen::Vector3d moment = chain.data().links.get(&LinkBlock::moment, k) - 0.5 * l * weight;
      worst = std::max(worst, (moment - 0.5 * l * expected).norm() / (0.5 * l * expected.norm()));
    }
    std::cout << (profile ? "profile" : "uniform") << " current: section drag against Morison, worst " << worst << "\n";
    EXPECT_LT(worst, 1e-12);
  }
}

// With a winch, the drum's slots take the base section's properties: the links paid out have its mass
// per length and radius.
TEST(Sections, WinchPaysOutTheBaseSection) {
  CableSimulator sim(loadConfigString(
      "cable: {links: 10, length: 20.0, diameter: 0.03, mass_per_length: 0.8,\n"
      "        sections: [{length: 10.0, diameter: 0.05, mass_per_length: 4.0}, {}]}\n"
      "load: {mass: 100.0}\n"
      "winch: {max_length: 30.0, speed: 1.0, max_speed: 1.0, max_acceleration: 1.0}\n"
      "simulation: {dt: 0.001}\n"));
  for (int i = 0; i < 8000; ++i) ASSERT_TRUE(sim.step().ok);
  SimulationSnapshot snap;
  sim.snapshot(snap);
  const LinkProperties& p = sim.properties();
  EXPECT_GT(sim.linksAdded(), 2);
  for (int k = snap.first_link; k < p.n; ++k) {
    const bool base = k < p.n - 5;
    EXPECT_NEAR(p.mass(k) / p.length(k), base ? 4.0 : 0.8, 1e-12) << "slot " << k;
    EXPECT_DOUBLE_EQ(p.radius(k), base ? 0.025 : 0.015) << "slot " << k;
  }
  EXPECT_NEAR(p.mass.sum(), 4.0 * (snap.deployed_length - 10.0) + 0.8 * 10.0, 1e-9);
}

// The stable step sees the light section under the heavy section's tension, and point masses do not
// make it less conservative.
TEST(Sections, StableStepCountsEverySection) {
  const CableParams p = loadConfigString(kTwoSections);
  const StableStep s = estimateStableStep(p, deriveLinkProperties(p));
  EXPECT_NE(s.mode.find("bending of link 11 "), std::string::npos) << s.mode;  // the light links: link 11 on
  std::cout << "two sections: limit " << s.limit << " s (" << s.mode << ")\n";
  // The zigzag of rigid links under the top tension, 12 T / (m l) (stable_step.cpp; no current, no springs).
  const double tension = weightBelow(0.0), m = 0.8 * 2.0 + kRho * M_PI * 0.015 * 0.015 * 2.0;
  EXPECT_NEAR(s.rate, std::sqrt(12.0 * tension / (m * 2.0)), 1e-9 * s.rate);
}
