// Independent reference for validating the cable simulator: a chain of rigid links on
// ball joints, simulated by MuJoCo (tested against MuJoCo 2.2.2, Debian libmujoco-dev).
//
// Frame convention: the world frame is z DOWN; gravity acts along +z (MuJoCo's gravity is
// set to (0, 0, +g)). The base of link 1 is fixed at the origin; link k's base end is the
// far end of link k-1; the link axis (base end -> far end) of link k is rotation[k].col(2).
//
// Not part of the package build: compile by hand, e.g.
//   g++ -std=c++17 -O2 -I/usr/include/eigen3 test/reference/mujoco_chain.cpp
//       test/reference/mujoco_chain_demo.cpp -lmujoco -o /tmp/mujoco_chain_demo   (one line)
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cable_reference {

struct ChainSpec {
  std::vector<double> length;              // (n) link lengths [m]
  std::vector<double> mass;                // (n) link masses [kg]
  std::vector<double> inertia_transverse;  // (n) about the link's CoM, across the axis [kg m^2]
  std::vector<double> inertia_polar;       // (n) about the link axis [kg m^2]
  double load_mass = 0.0;                  // point mass at the far end of link n [kg] (0: none)
  double gravity = 9.81;                   // [m/s^2], acting along +z (the frame is z DOWN)
  std::vector<Eigen::Matrix3d> rotation;   // (n) initial orientation of each link in the world frame;
                                           // the link axis (base end -> far end) is rotation[k].col(2)
  std::vector<Eigen::Vector3d> angular_velocity;  // (n) initial angular velocity of each link, world frame [rad/s]
};

struct ChainTrajectory {
  std::vector<double> time;                        // [s]
  std::vector<std::vector<Eigen::Vector3d>> ends;  // ends[sample][k], k = 0..n: k = 0 the base (origin),
                                                   // k the far end of link k [m]
  // Additions beyond the minimal interface (diagnostics), one entry per sample, as computed
  // by MuJoCo's mj_energyPos / mj_energyVel on the sampled state:
  std::vector<double> potential_energy;  // -sum m g z_com (includes the load) [J]
  std::vector<double> kinetic_energy;    // [J]
};

// Integrates with MuJoCo's RK4 integrator at time step dt for `duration`, sampling every
// `sample_every` seconds (sample 0 = the initial state). sample_every is rounded to a whole
// number of steps (at least 1) and duration to a whole number of steps; time[s] is
// (sample index) * (steps per sample) * dt.
// Throws std::runtime_error with MuJoCo's message if the model fails to load, and
// std::invalid_argument for inconsistent input sizes or non-positive dt / sample_every.
ChainTrajectory simulateChainInMujoco(const ChainSpec& spec, double dt, double duration, double sample_every);

// --- Helpers exposed for inspection / testing -------------------------------------------

// The MJCF model generated for `spec` at time step dt (links in their reference pose: every
// link body's z axis is the link axis; the initial configuration is set through qpos).
std::string chainMjcf(const ChainSpec& spec, double dt);

// Initial MuJoCo state for `spec`: qpos (4 n: one quaternion w,x,y,z per ball joint) and
// qvel (3 n: per joint the angular velocity of the link relative to its parent, in the
// link's own frame). See the derivation in mujoco_chain.cpp.
void chainInitialState(const ChainSpec& spec, std::vector<double>& qpos, std::vector<double>& qvel);

}  // namespace cable_reference
