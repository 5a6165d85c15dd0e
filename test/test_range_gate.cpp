// Parameters filled in by hand in C++ meet the same ranges as a config: the simulator refuses a value out
// of its key's range with the key and the range the config loader gives for the same value in a config
// (one table, params/key_ranges.h; the gate, checkConfigRanges). Each case sets one value both ways and
// compares the two refusals' key and allowed range.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/input_gate.h"
#include "cable_dynamics/simulation/cable_simulator.h"

using namespace cable_dynamics;

namespace {

// A winch, sections, a seabed grid, an attached ROV that moves: most of the gate's branches.
const char* const kWinchCable = R"(
cable: {links: 4, length: 8.0, diameter: 0.03, mass_per_length: 1.0,
        stiffness: {model: bending, bending_rigidity: 10.0}, damping: {elevation: 0.1},
        limits: {max_tension: 1.0e4},
        sections: [{length: 4.0}, {diameter: 0.04}]}
load: {mass: 10.0, volume: 0.001, mode: attached, motion: {amplitude: [0.1, 0, 0], period: 10.0}}
seabed: {grid: {origin: [-50, -50], spacing: [100, 100], depth: [[30, 30], [30, 30]]}}
winch: {max_length: 12.0, speed: 0.5, schedule: [{time: 1.0, speed: 0.2}, {time: 2.0, length: 10.0}]}
fluid: {current_profile: [[0.0, 0.1, 0.0, 0.0], [100.0, 0.0, 0.0, 0.0]]}
)";

// An ROV body, attachments.
const char* const kBodyCable = R"(
cable: {links: 4, length: 8.0, diameter: 0.03, mass_per_length: 1.0}
load: {mass: 11.5, volume: 0.0112, mode: body,
       body: {inertia: [0.16, 0.16, 0.16], station_keeping: {position_gain: [50, 50, 50], max_force: 80.0}}}
attachments: [{arc_length: 2.0, mass: 1.0, volume: 0.01}]
)";

struct Refusal {
  std::string key;       ///< "(accepted)" when nothing was refused
  std::string expected;  ///< the message's allowed range: what follows ": expected "
};

Refusal refusalOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    const std::size_t at = what.find(": expected ");
    return {e.key(), at == std::string::npos ? what : what.substr(at + 11)};
  }
  return {"(accepted)", ""};
}

struct Case {
  const char* base;                         ///< kWinchCable or kBodyCable
  std::string override_;                    ///< key=value, as cable_sim's --set takes it
  std::function<void(CableParams&)> by_hand;  ///< the same value, set in the loaded parameters
};

void expectSameRefusal(const Case& c) {
  SCOPED_TRACE(c.override_);
  const Refusal loaded = refusalOf([&] { loadConfigString(c.base, {c.override_}); });
  CableParams p = loadConfigString(c.base);
  c.by_hand(p);
  const Refusal built = refusalOf([&] { CableSimulator sim(p); });
  EXPECT_NE(loaded.key, "(accepted)");
  EXPECT_EQ(built.key, loaded.key);
  EXPECT_EQ(built.expected, loaded.expected);
}

}  // namespace

TEST(RangeGate, TheBaseConfigsRun) {
  for (const char* base : {kWinchCable, kBodyCable}) {
    EXPECT_EQ(refusalOf([&] { CableSimulator sim(loadConfigString(base)); }).key, "(accepted)");
  }
}

TEST(RangeGate, AValueSetByHandIsRefusedAsInAConfig) {
  const std::vector<Case> cases = {
      {kWinchCable, "cable.links=0", [](CableParams& p) { p.links = 0; }},
      {kWinchCable, "cable.link_lengths=[2.0, -1.0, 2.0, 2.0]", [](CableParams& p) { p.link_lengths[1] = -1.0; }},
      {kWinchCable, "cable.diameter=20", [](CableParams& p) { p.diameter = 20.0; }},
      {kWinchCable, "cable.mass_per_length=-1", [](CableParams& p) { p.mass_per_length = -1.0; }},
      {kWinchCable, "cable.limits.max_tension=-3", [](CableParams& p) { p.limits.max_tension = -3.0; }},
      {kWinchCable, "cable.stiffness.bending_rigidity=-5", [](CableParams& p) { p.stiffness.bending_rigidity = -5.0; }},
      {kWinchCable, "cable.damping.torsion=.nan", [](CableParams& p) { p.damping.torsion = std::nan(""); }},
      {kWinchCable, "load.mass=-1", [](CableParams& p) { p.load.mass = -1.0; }},
      {kWinchCable, "load.coupling.stiffness=0", [](CableParams& p) { p.load.coupling_stiffness = 0.0; }},
      {kWinchCable, "load.motion.offset=[0, 2e5, 0]", [](CableParams& p) { p.load.motion.offset.y() = 2e5; }},
      {kWinchCable, "load.motion.period=0", [](CableParams& p) { p.load.motion.period = 0.0; }},
      {kWinchCable, "base.hang_off=[0, 0, 5000]", [](CableParams& p) { p.base.hang_off.z() = 5000.0; }},
      {kWinchCable, "fluid.density=-1", [](CableParams& p) { p.fluid.density = -1.0; }},
      {kWinchCable, "fluid.drag_points=9", [](CableParams& p) { p.fluid.drag_points = 9; }},
      {kWinchCable, "gravity=200", [](CableParams& p) { p.gravity = 200.0; }},
      {kWinchCable, "seabed.penetration=0", [](CableParams& p) { p.seabed.penetration = 0.0; }},
      {kWinchCable, "seabed.friction.velocity=0", [](CableParams& p) { p.seabed.friction_velocity = 0.0; }},
      {kWinchCable, "seabed.contact_points=17", [](CableParams& p) { p.seabed.contact_points = 17; }},
      {kWinchCable, "initial.elevation=[0, 0, 4, 0]", [](CableParams& p) { p.initial.elevation[2] = 4.0; }},
      {kWinchCable, "simulation.dt=0.5", [](CableParams& p) { p.simulation.dt = 0.5; }},
      {kWinchCable, "simulation.rho_infinity=2", [](CableParams& p) { p.simulation.rho_infinity = 2.0; }},
      {kWinchCable, "winch.speed=5", [](CableParams& p) { p.winch.speed = 5.0; }},
      {kWinchCable, "winch.min_length=0.5", [](CableParams& p) { p.winch.min_length = 0.5; }},
      {kWinchCable, "winch.max_acceleration=0", [](CableParams& p) { p.winch.max_acceleration = 0.0; }},
      {kBodyCable, "load.body.inertia=[1, 0, 0, 0, 1, 0, 0, 0, 2e9]", [](CableParams& p) { p.load.body.inertia(2, 2) = 2e9; }},
      {kBodyCable, "load.body.station_keeping.max_force=-1", [](CableParams& p) { p.load.body.max_force = -1.0; }},
      {kBodyCable, "load.body.center_of_buoyancy=[0, 0, 101]", [](CableParams& p) { p.load.body.center_of_buoyancy.z() = 101.0; }},
  };
  for (const Case& c : cases) expectSameRefusal(c);
}

// List rows cannot be set with key=value: the same comparison with the config's text changed.
TEST(RangeGate, AListRowSetByHandIsRefusedAsInAConfig) {
  const auto compare = [](const std::string& base, const std::string& from, const std::string& to,
                          const std::function<void(CableParams&)>& by_hand) {
    SCOPED_TRACE(to);
    std::string changed = base;
    changed.replace(changed.find(from), from.size(), to);
    const Refusal loaded = refusalOf([&] { loadConfigString(changed); });
    CableParams p = loadConfigString(base);
    by_hand(p);
    const Refusal built = refusalOf([&] { CableSimulator sim(p); });
    EXPECT_NE(loaded.key, "(accepted)");
    EXPECT_EQ(built.key, loaded.key);
    EXPECT_EQ(built.expected, loaded.expected);
  };
  compare(kWinchCable, "{diameter: 0.04}", "{diameter: 0.04, drag_normal: 101}",
          [](CableParams& p) { p.sections[1].drag_normal = 101.0; });
  compare(kWinchCable, "{time: 2.0, length: 10.0}", "{time: 2.0, length: 13.0}",
          [](CableParams& p) { p.winch.schedule[1].value = 13.0; });
  compare(kWinchCable, "[[30, 30], [30, 30]]", "[[30, 30], [30, 2e5]]", [](CableParams& p) { p.seabed.grid.depth(1, 1) = 2e5; });
  compare(kBodyCable, "{arc_length: 2.0, mass: 1.0, volume: 0.01}", "{arc_length: 9.0, mass: 1.0, volume: 0.01}",
          [](CableParams& p) { p.attachments[0].arc_length = 9.0; });
}

// What a config cannot get wrong but a hand can: sizes, the winch's counted slots, unit directions. Each
// refusal names the field.
TEST(RangeGate, ShapesAConfigGivesAreCheckedToo) {
  EXPECT_EQ(refusalOf([] { CableSimulator sim{CableParams{}}; }).key, "cable.link_lengths")
      << "default parameters have no link lengths: refused, not an out-of-range read";
  const auto refused = [](const char* base, const std::function<void(CableParams&)>& by_hand) {
    CableParams p = loadConfigString(base);
    by_hand(p);
    return refusalOf([&] { CableSimulator sim(p); }).key;
  };
  EXPECT_EQ(refused(kWinchCable, [](CableParams& p) { p.initial.torsion.pop_back(); }), "initial.torsion");
  EXPECT_EQ(refused(kWinchCable, [](CableParams& p) { p.winch.stored_links = 0; }), "winch.stored_links");
  EXPECT_EQ(refused(kWinchCable, [](CableParams& p) { p.winch.link_length = 1.0; }), "winch.link_length");
  EXPECT_EQ(refused(kWinchCable, [](CableParams& p) { p.sections[0].length = 3.0; }), "cable.sections");
  EXPECT_EQ(refused(kWinchCable, [](CableParams& p) { p.load.direction = Eigen::Vector3d(0, 0, -2); }), "load.direction");
  EXPECT_EQ(refused(kWinchCable, [](CableParams& p) { std::swap(p.fluid.current_profile[0], p.fluid.current_profile[1]); }),
            "fluid.current_profile[1]");
  EXPECT_EQ(refused(kWinchCable, [](CableParams& p) { p.winch.schedule[1].time = 0.5; }), "winch.schedule[1].time");
}

// Live retuning from C++ meets the same gate, and a refusal leaves the running model as it was.
TEST(RangeGate, RetuneRefusesAValueOutOfRangeAndKeepsTheModel) {
  CableSimulator sim(loadConfigString(kWinchCable));
  CableParams tuned = sim.params();
  tuned.fluid.drag_normal = -0.5;
  EXPECT_EQ(refusalOf([&] { sim.retune(tuned); }).key, "fluid.drag_normal");
  EXPECT_EQ(sim.params().fluid.drag_normal, 1.2);
  tuned.fluid.drag_normal = 1.5;
  sim.retune(tuned);
  EXPECT_EQ(sim.params().fluid.drag_normal, 1.5);
}
