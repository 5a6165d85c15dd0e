// No heap allocation in a simulation step, for both formulations and every integrator. Two guards:
// - every allocation of the test binary is counted while a step runs: malloc, calloc, realloc,
//   posix_memalign, aligned_alloc and memalign are replaced in this program (glibc lets a program replace
//   them: "Replacing malloc" in its manual) by counters that forward to glibc's own allocator, and the
//   global operator new (std::vector, std::string, `new`) reaches them through libstdc++'s malloc call;
//   a step must count zero;
// - the core is compiled with EIGEN_RUNTIME_NO_MALLOC (test/tests.cmake) and Eigen's allocator is switched
//   off around the calls, so an Eigen allocation aborts at once (its stack names the culprit).
#ifndef EIGEN_RUNTIME_NO_MALLOC
#error "build this test with EIGEN_RUNTIME_NO_MALLOC"
#endif

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/params/config_loader.h"
#include "light_tether_rov.h"

// glibc's allocator under its exported internal names (GLIBC_2.2.5): what the replacements forward to.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* p);
}

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
inline void count() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

extern "C" {
void* malloc(std::size_t size) {
  count();
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  count();
  return __libc_realloc(p, size);
}
void free(void* p) { __libc_free(p); }
void* memalign(std::size_t alignment, std::size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  count();
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
}  // extern "C"

using namespace cable_dynamics;

namespace {

/// Both guards on between start() and stop(); stop() returns the allocations counted in between.
struct AllocationGuard {
  void start() {
    g_allocations = 0;
    g_counting = true;
    Eigen::internal::set_is_malloc_allowed(false);
  }
  long stop() {
    Eigen::internal::set_is_malloc_allowed(true);
    g_counting = false;
    return g_allocations.load();
  }
};

void expectNoAllocation(const std::vector<std::string>& overrides) {
  CableParams p = loadConfigString(R"(
cable: {links: 8, length: 16.0, diameter: 0.03, mass_per_length: 1.0}
load: {mass: 5.0, volume: 0.002, drag_area: 0.1}
fluid: {density: 1025.0, current: [1.0, 0.2, 0.0]}
base: {motion: {amplitude: [0, 0, 0.5], period: 6.0}}
initial: {elevation: 0.3}
)",
                                   overrides);
  CableSimulator sim(p);
  ASSERT_TRUE(sim.step().ok);  // first step outside the guard (nothing is expected to allocate, though)
  Eigen::VectorXd xdot(sim.dynamics().stateSize());
  AllocationGuard guard;
  guard.start();
  bool ok = true;
  for (int i = 0; i < 20; ++i) ok = sim.step().ok && ok;
  ok = sim.dynamics().derivative(sim.state(), EndInputs(), xdot) && ok;
  const long allocations = guard.stop();
  EXPECT_TRUE(ok);
  EXPECT_EQ(allocations, 0) << "heap allocations in 20 steps and a derivative";
}

}  // namespace

TEST(NoAllocation, RecursiveRk4Step) { expectNoAllocation({"simulation.formulation=recursive"}); }

// Live tuning rebuilds the chain's constants between steps (that allocates); the steps after it do not.
TEST(NoAllocation, StepAfterARetune) {
  const char* cable =
      "cable: {links: 8, length: 16.0, diameter: 0.03, mass_per_length: 1.0}\n"
      "load: {mass: 5.0, volume: 0.002, mode: attached, coupling: {integral_time: 2.0}}\n"
      "fluid: {density: 1025.0, current: [1.0, 0.2, 0.0]}\n"
      "initial: {elevation: 0.3}\n";
  CableSimulator sim(loadConfigString(cable));
  ASSERT_TRUE(sim.step().ok);
  // With a bumpless new stiffness and the coupling's integral action, both between steps.
  sim.retune(loadConfigString(cable, {"fluid.drag_normal=2.0", "fluid.added_mass=0.5", "load.coupling.damping=100",
                                      "load.coupling.stiffness=5000"}));
  AllocationGuard guard;
  guard.start();
  bool ok = true;
  for (int i = 0; i < 20; ++i) ok = sim.step().ok && ok;
  const long allocations = guard.stop();
  EXPECT_TRUE(ok);
  EXPECT_EQ(allocations, 0) << "heap allocations in the 20 steps after a retune";
}

TEST(NoAllocation, RecursiveRk4StepInADepthProfile) {
  // The drag point by point (a current that changes with depth) instead of the uniform shortcut.
  expectNoAllocation({"fluid.current=[0, 0, 0]", "fluid.current_profile=[[0, 1.0, 0.2, 0.0], [20, 0.3, 0.0, 0.0]]"});
}

TEST(NoAllocation, DenseRk4Step) { expectNoAllocation({"simulation.formulation=paper"}); }

TEST(NoAllocation, BendingSpringsStep) {
  expectNoAllocation({"cable.stiffness={model: bending, elevation: 1.0, torsion: 0.1}", "cable.damping={elevation: 0.1}"});
}

TEST(NoAllocation, SemiImplicitStep) {
  expectNoAllocation({"simulation.integrator=semi_implicit", "simulation.dt=0.01"});
}

TEST(NoAllocation, ImplicitStep) {
  // The implicit integrator (issue 15): its recursion's per-link terms are sized in its constructor; with
  // springs, dampers, drag in a uniform current and in a depth profile, and an attached load.
  const std::string springs = "cable.stiffness={model: bending, bending_rigidity: 50.0, torsional_rigidity: 20.0}";
  expectNoAllocation({"simulation.integrator=implicit", "simulation.dt=0.01", springs, "cable.damping={elevation: 0.5, torsion: 0.01}"});
  expectNoAllocation({"simulation.integrator=implicit", "simulation.dt=0.01", "simulation.rho_infinity=0.5", springs,
                      "fluid.current=[0, 0, 0]", "fluid.current_profile=[[0, 1.0, 0.2, 0.0], [20, 0.3, 0.0, 0.0]]",
                      "load.mode=attached"});
  // With the seabed in its matrix (friction: its damping joins the drag's) and a clamped tip: the tip
  // starts 15.3 m deep, and the ROV's coupling holds it there, against a bed at 15 m.
  expectNoAllocation({"simulation.integrator=implicit", "simulation.dt=0.01", springs,
                      "seabed={depth: 15.0, friction: {axial: 0.3, lateral: 0.6}}", "load.mode=attached",
                      "load.fixity=clamped"});
}

TEST(NoAllocation, AxialElasticity) {
  // The stretches (docs/MODEL.md section 12): RK4 (the prismatic joint in the recursion, the largest
  // tension and the snaps watched after each step) and the implicit step (its stretch vectors and the
  // fold in its recursion), a damper and a seabed with them.
  const std::string axial = "cable.axial_stiffness=2.0e5";
  expectNoAllocation({axial, "cable.axial_damping=100.0", "simulation.dt=0.0002"});
  expectNoAllocation({axial, "cable.axial_damping=100.0", "simulation.integrator=implicit", "simulation.dt=0.01",
                      "cable.stiffness={model: bending, bending_rigidity: 50.0}", "seabed={depth: 15.0}"});
}

TEST(NoAllocation, ExactAnchor) {
  // The exact anchor (docs/MODEL.md section 14): RK4's hold (a second backward pass and a 3x3 eigen-solve
  // in every evaluation), with and without the stretch; the implicit step's internal hold. The anchor 6 m
  // out and 4 m up from the straight-down tip: the heaving base pulls a sagging line (a straight one between
  // two held points could not follow the heave).
  const std::vector<std::string> anchored = {"load.mode=anchored", "load.motion.offset=[6.0, 0.0, 4.0]",
                                             "initial.mode=equilibrium"};
  std::vector<std::string> o = anchored;
  expectNoAllocation(o);
  o.insert(o.end(), {"cable.axial_stiffness=2.0e5", "simulation.dt=0.0002"});
  expectNoAllocation(o);
  o = anchored;
  o.insert(o.end(), {"simulation.integrator=implicit", "simulation.dt=0.01"});
  expectNoAllocation(o);
}

TEST(NoAllocation, LimitsInTheSnapshot) {
  // The limits (dynamics/cable_limits.h) are computed in every snapshot, which cable_sim and the node take
  // each sample or cycle: bend radii against both clamps, utilisation with a tension and a per-section bend
  // limit, the seabed clearance. After the first snapshot (it sizes the outputs) no snapshot allocates.
  CableParams p = loadConfigString(R"(
cable: {links: 8, length: 16.0, diameter: 0.03, mass_per_length: 1.0,
        stiffness: {model: bending, bending_rigidity: 50.0},
        limits: {max_tension: 100.0, min_bend_radius: 2.0, min_seabed_clearance: 1.0},
        sections: [{length: 8.0}, {length: 8.0, limits: {min_bend_radius: 3.0}}]}
load: {mass: 5.0, volume: 0.002, mode: anchored, fixity: clamped}
fluid: {density: 1025.0, current: [1.0, 0.2, 0.0]}
seabed: {depth: 18.0}
initial: {elevation: 0.3}
simulation: {integrator: implicit, dt: 0.01}
)");
  CableSimulator sim(p);
  SimulationSnapshot s;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(sim.step().ok);
  sim.snapshot(s);  // sizes the snapshot's vectors
  AllocationGuard guard;
  guard.start();
  bool ok = true;
  for (int i = 0; i < 5; ++i) {
    ok = sim.step().ok && ok;
    sim.snapshot(s);
  }
  const long allocations = guard.stop();
  EXPECT_TRUE(ok);
  EXPECT_EQ(allocations, 0) << "heap allocations in 5 steps and snapshots";
  EXPECT_GT(s.chain.limits.max_utilisation, 0.0);  // the limits were computed
  EXPECT_EQ(s.chain.limits.bend_radius.size(), 8);
}

TEST(NoAllocation, SectionsAndAttachments) {
  // Per-link section properties, and attachments with drag (their own loop in the drag pass), in both
  // formulations and in a depth profile (the statics' and the dynamics' point-by-point path).
  const std::vector<std::string> sections = {
      "cable.sections=[{length: 6.0, diameter: 0.06, mass_per_length: 3.0, drag_normal: 1.5}, {added_mass: 0.5}]",
      "attachments=[{arc_length: 7.0, mass: 2.0, volume: 0.01, drag_area: 0.2, added_mass: 1.0}, "
      "{arc_length: 12.5, mass: 8.0, volume: 0.001, drag_area: 0.05}]"};
  for (const char* extra : {"simulation.formulation=recursive", "simulation.formulation=paper",
                            "fluid.current_profile=[[0, 1.0, 0.2, 0.0], [20, 0.3, 0.0, 0.0]]"}) {
    std::vector<std::string> o = sections;
    o.push_back(extra);
    if (std::string(extra).find("profile") != std::string::npos) o.push_back("fluid.current=[0, 0, 0]");
    expectNoAllocation(o);
  }
}

TEST(NoAllocation, RovBodyWithStationKeepingAndThrust) {
  // load.mode body: the body's terms in every evaluation, the station keeper's pose and wrench before each
  // step, a thrust command between steps; RK4, the implicit step, the semi-implicit step, and RK4 on the
  // paper's dense formulation.
  CableParams p = loadConfigString(std::string(cable_dynamics_test::kLightTetherRov) + "simulation: {dt: 0.002}\n");
  struct Scheme {
    const char* name;
    Integrator integrator;
    Formulation formulation;
    double dt;  ///< [s]
  };
  // The semi-implicit step diverges on this light tether from 2 ms with the thrust step (MODEL.md section 6).
  for (const Scheme& scheme : {Scheme{"rk4", Integrator::kRk4, Formulation::kRecursive, 0.0005},
                               Scheme{"implicit", Integrator::kImplicit, Formulation::kRecursive, 0.01},
                               Scheme{"semi_implicit", Integrator::kSemiImplicit, Formulation::kRecursive, 0.001},
                               Scheme{"rk4 (paper)", Integrator::kRk4, Formulation::kPaper, 0.0005}}) {
    SCOPED_TRACE(scheme.name);
    p.simulation.integrator = scheme.integrator;
    p.simulation.formulation = scheme.formulation;
    p.simulation.dt = scheme.dt;
    CableSimulator sim(p);
    ASSERT_TRUE(sim.step().ok);
    AllocationGuard guard;
    guard.start();
    bool ok = true;
    for (int i = 0; i < 200; ++i) {
      if (i == 100) sim.setBodyThrust(Eigen::Vector3d(20.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 1.0));
      ok = sim.step().ok && ok;
    }
    const long allocations = guard.stop();
    EXPECT_TRUE(ok);
    EXPECT_EQ(allocations, 0) << "heap allocations in 200 steps of an ROV body";
  }
}

namespace {

/// Steps `sim` paying out `steps` steps, then hauling in as many, under the allocation guard: the heap
/// allocations (0 expected) and whether every step was ok; links are added and removed in those steps.
long allocationsPayingOutAndHaulingIn(CableSimulator& sim, int steps, bool& ok) {
  AllocationGuard guard;
  guard.start();
  ok = true;
  for (int i = 0; i < steps; ++i) ok = sim.step().ok && ok;
  sim.commandWinchSpeed(-2.0);
  for (int i = 0; i < steps; ++i) ok = sim.step().ok && ok;
  return guard.stop();
}

}  // namespace

TEST(NoAllocation, WinchPayingOutAndHaulingIn) {
  // Links added and removed at the winch, in the steps where that happens: everything is sized for
  // the longest deployment at start.
  CableParams p = loadConfigString(R"(
cable: {links: 8, length: 16.0, diameter: 0.03, mass_per_length: 1.0, stiffness: {model: bending, bending_rigidity: 5.0}}
load: {mass: 5.0, volume: 0.002, drag_area: 0.1}
fluid: {density: 1025.0, current: [1.0, 0.2, 0.0]}
initial: {elevation: 0.3}
winch: {max_length: 40.0, max_speed: 2.0, max_acceleration: 100.0, speed: 2.0}
)");
  for (const char* integrator : {"rk4", "implicit"}) {
    SCOPED_TRACE(integrator);
    p.simulation.integrator = std::string(integrator) == "rk4" ? Integrator::kRk4 : Integrator::kImplicit;
    CableSimulator sim(p);
    ASSERT_TRUE(sim.step().ok);
    bool ok = false;
    EXPECT_EQ(allocationsPayingOutAndHaulingIn(sim, 3000, ok), 0) << "heap allocations while paying out and hauling in";
    EXPECT_TRUE(ok);
    EXPECT_GE(sim.linksAdded(), 2);
    EXPECT_GE(sim.linksRemoved(), 2);
  }
}

TEST(NoAllocation, WinchPayingOutAStretchingCable) {
  // Axial elasticity through the links the winch adds and removes (their stretches split and merged).
  for (const char* integrator : {"rk4", "implicit"}) {
    SCOPED_TRACE(integrator);
    CableParams p = loadConfigString(std::string(R"(
cable: {links: 8, length: 16.0, diameter: 0.03, mass_per_length: 1.0, axial_stiffness: 1.0e6, axial_damping: 100.0}
load: {mass: 5.0, volume: 0.002, drag_area: 0.1}
fluid: {density: 1025.0, current: [1.0, 0.2, 0.0]}
initial: {elevation: 0.3}
winch: {max_length: 40.0, max_speed: 2.0, max_acceleration: 100.0, speed: 2.0}
simulation: {dt: 0.0005, integrator: )") + integrator + "}\n");
    CableSimulator sim(p);
    ASSERT_TRUE(sim.step().ok);
    bool ok = false;
    EXPECT_EQ(allocationsPayingOutAndHaulingIn(sim, 6000, ok), 0)
        << "heap allocations while paying out and hauling in a stretching cable";
    EXPECT_TRUE(ok);
    EXPECT_GE(sim.linksAdded(), 2);
    EXPECT_GE(sim.linksRemoved(), 2);
  }
}

TEST(NoAllocation, GuardIsActive) {
  // The Eigen guard itself works: an allocation under it aborts (checked in a death test).
  EXPECT_DEATH(
      {
        Eigen::internal::set_is_malloc_allowed(false);
        Eigen::VectorXd v(1000);
        v.setZero();
      },
      "");
}

// The counter sees each way a step could allocate: a std::vector, a std::string longer than its inline
// buffer, `new`, std::make_shared, malloc, an Eigen vector (Eigen's guard off here, so only counted).
TEST(NoAllocation, CounterSeesEveryAllocator) {
  const auto counted = [](auto&& allocate) {
    g_allocations = 0;
    g_counting = true;
    allocate();
    g_counting = false;
    return g_allocations.load();
  };
  EXPECT_GE(counted([] { std::vector<double> v(10, 1.0); EXPECT_EQ(v.size(), 10u); }), 1);
  EXPECT_GE(counted([] { std::string s(100, 'x'); EXPECT_EQ(s.size(), 100u); }), 1);
  EXPECT_GE(counted([] { std::unique_ptr<int> p(new int(3)); EXPECT_EQ(*p, 3); }), 1);
  EXPECT_GE(counted([] { auto p = std::make_shared<double>(2.0); EXPECT_EQ(*p, 2.0); }), 1);
  EXPECT_GE(counted([] { void* p = std::malloc(64); EXPECT_NE(p, nullptr); std::free(p); }), 1);
  EXPECT_GE(counted([] { Eigen::VectorXd v = Eigen::VectorXd::Ones(100); EXPECT_EQ(v.sum(), 100.0); }), 1);
  // And nothing where nothing is allocated (a fixed-size Eigen vector, on the stack).
  double sum = 0.0;
  EXPECT_EQ(counted([&sum] { Eigen::Vector3d v(1, 2, 3); sum = v.sum(); }), 0);
  EXPECT_EQ(sum, 6.0);
}
