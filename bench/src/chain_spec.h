#pragma once
/// \file
/// \brief The one chain every system of the benchmark simulates, and the interface each system offers.
///
/// Frame: the project's paper frame, z pointing down, origin at the fixed base; gravity along +z.
/// Link k (0-based) is a rigid cylinder hinged at its base end; its body frame has the origin at the
/// joint and the z axis along the link. The point load at the tip is folded into the last link.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/StdVector>

#include "cable_dynamics/params/cable_params.h"

namespace bench {

struct ChainSpec {
  int n = 0;
  double dt = 1e-3;       ///< [s]
  double gravity = 9.81;  ///< along +z (down) [m/s^2]
  /// Per link, from cable_dynamics::deriveLinkProperties() (the load not yet folded in).
  std::vector<double> length, mass, inertia_transverse, inertia_polar;
  double load_mass = 0.0;  ///< point mass at the far end of the last link [kg]
  /// Initial world orientation of each link (R * e_z = link axis), from the project's initial state.
  std::vector<Eigen::Matrix3d, Eigen::aligned_allocator<Eigen::Matrix3d>> rotation;

  /// Rigid-body data of link k with the load folded into the last link: mass, centre of mass on the
  /// link axis (distance from the joint), transverse inertia about that centre of mass; the polar
  /// inertia is unchanged (the load sits on the axis).
  double bodyMass(int k) const;
  double bodyCom(int k) const;
  double bodyInertiaTransverse(int k) const;
  double bodyInertiaPolar(int k) const { return inertia_polar[k]; }

  /// Rotation of link k relative to link k-1 (relative to the world for k = 0).
  Eigen::Matrix3d relativeRotation(int k) const;

  /// Energy scale of the correctness check: potential energy the chain can release, E(start, at rest)
  /// minus E(hanging straight down) [J]: an upper bound of the kinetic energy it can ever reach.
  double releasableEnergy() const;
};

/// The configuration text (YAML) of the benchmark chain for cable_dynamics::loadConfigString().
std::string projectConfig(int links);

/// Builds the spec from the project's parameters and the link axes of its initial state.
ChainSpec makeSpec(const cable_dynamics::CableParams& params, const std::vector<Eigen::Vector3d>& axes);

/// One simulator of the chain. Construction is not timed; step() is.
class System {
 public:
  virtual ~System() = default;
  /// Back to the initial state (at rest) at t = 0.
  virtual void reset() = 0;
  /// One step of dt: classical RK4, four evaluations of the forward dynamics.
  virtual void step() = 0;
  /// Kinetic + gravitational potential energy (zero height at the base) [J]. Not timed.
  virtual double energy() = 0;
  /// Far end of the last link [m]. Not timed.
  virtual Eigen::Vector3d tip() = 0;
  /// False when a step since the last reset() failed or the engine flagged the simulation as unstable.
  virtual bool healthy() const { return true; }
  /// Anything the notes should mention (retried steps, engine warnings); empty if nothing.
  virtual std::string note() const { return {}; }
};

/// One column of the table: a name and how to build the system for a spec.
struct Engine {
  std::string name;
  std::string how;  ///< joint type and integrator, for the legend
  std::unique_ptr<System> (*make)(const ChainSpec&);
};

std::vector<Engine> engines();  ///< the engines compiled in (main.cpp)

#ifdef BENCH_HAVE_MUJOCO
std::unique_ptr<System> makeMujoco(const ChainSpec& spec);
#endif
#ifdef BENCH_HAVE_DART
std::unique_ptr<System> makeDart(const ChainSpec& spec);
#endif
#ifdef BENCH_HAVE_SIMBODY
std::unique_ptr<System> makeSimbody(const ChainSpec& spec);
#endif
#ifdef BENCH_HAVE_KDL
std::unique_ptr<System> makeKdl(const ChainSpec& spec);
#endif

}  // namespace bench
