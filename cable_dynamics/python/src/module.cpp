/// \file
/// \brief The Python module `cable_dynamics`: the simulator built from a config file or a dict, stepped,
///        read as numpy arrays, driven through its inputs. A thin layer over python_simulator.h.

#include <functional>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "cable_dynamics/params/config_loader.h"
#include "config_from_python.h"
#include "python_simulator.h"

namespace py = pybind11;
using namespace pybind11::literals;  // "name"_a; a .cpp, not a header

namespace cable_dynamics {
namespace python {
namespace {

PythonSimulator* fromFile(const std::string& path, const std::vector<std::string>& overrides) {
  return new PythonSimulator(loadConfigFile(path, overrides));
}

PythonSimulator* fromDict(const py::dict& config, const std::vector<std::string>& overrides) {
  YAML::Node root = toYaml(config);
  for (const std::string& o : overrides) applyOverride(root, o);
  return new PythonSimulator(parseConfig(root));
}

const Eigen::Vector3d kZero = Eigen::Vector3d::Zero();
const Eigen::Vector4d kIdentity(0.0, 0.0, 0.0, 1.0);  // x, y, z, w

}  // namespace
}  // namespace python
}  // namespace cable_dynamics

PYBIND11_MODULE(_bindings, m) {  // cable_dynamics._bindings, re-exported by the package
  using namespace cable_dynamics;
  using namespace cable_dynamics::python;
  m.doc() =
      "The n-link umbilical of cable_dynamics (Gomes et al. 2016) from Python. Build a Simulator from a config "
      "file or a dict (the keys of docs/CONFIG.md), step it, read snapshots and the model's "
      "matrices as numpy arrays, set the current, the targets and the winch. Outputs are in the paper frame "
      "(base at the origin, z down); inputs in world axes (z up) from the base's rest position.";

  // A bad config value: the message names the key, the value and the allowed range.
  py::register_exception<ConfigError>(m, "ConfigError", PyExc_ValueError);

  py::class_<Snapshot>(m, "Snapshot", "One instant (SI units, paper frame: base at the origin, z down).")
      .def_readonly("time", &Snapshot::time, "simulated time since reset [s]")
      .def_readonly("q", &Snapshot::q, "(3n) paper coordinates [rad]")
      .def_readonly("qd", &Snapshot::qd, "(3n) their rates [rad/s]")
      .def_readonly("link_ends", &Snapshot::link_ends, "(n+1, 3) the base, then each link's far end [m]")
      .def_readonly("axes", &Snapshot::axes, "(n, 3) unit axis of each link, base end to far end")
      .def_readonly("tension", &Snapshot::tension, "(n) force along each link at its base end [N], 0 on a drum")
      .def_readonly("line_pull", &Snapshot::line_pull, "tension at the top (the winch) [N]")
      .def_readonly("load_force", &Snapshot::load_force, "(3) force the cable exerts on the load [N]")
      .def_readonly("base_force", &Snapshot::base_force, "(3) force the cable exerts on the base [N]")
      .def_readonly("coupling_force", &Snapshot::coupling_force, "(3) PD force of the anchor / ROV on the load [N]")
      .def_readonly("kinetic_energy", &Snapshot::kinetic_energy, "[J]")
      .def_readonly("potential_energy", &Snapshot::potential_energy, "gravity minus buoyancy [J]")
      .def_readonly("elastic_energy", &Snapshot::elastic_energy, "joint springs [J]")
      .def_readonly("dissipated_energy", &Snapshot::dissipated_energy, "since reset [J]")
      .def_readonly("work_input", &Snapshot::work_input, "done by the moving base and the coupling [J]")
      .def_readonly("total_energy", &Snapshot::total_energy, "the balance, constant up to the integrator [J]")
      .def_readonly("first_link", &Snapshot::first_link, "slots before it are on the winch's drum")
      .def_readonly("deployed_length", &Snapshot::deployed_length, "[m]")
      .def_readonly("winch_speed", &Snapshot::winch_speed, "+ paying out [m/s]")
      .def_readonly("seabed_force", &Snapshot::seabed_force, "(n, 3) the bottom's force on each link [N] (empty without a seabed)")
      .def_readonly("seabed_normal", &Snapshot::seabed_normal, "(n) its normal part [N]")
      .def_readonly("grounded_length", &Snapshot::grounded_length, "cable length on the bottom [m]")
      .def_readonly("stuck_length", &Snapshot::stuck_length,
                    "of the grounded length, what the static friction's anchors hold [m] (0 without static friction)")
      .def_readonly("touchdown_arc_length", &Snapshot::touchdown_arc_length,
                    "from the base, where the cable first touches the bottom [m]; -1 while nothing touches")
      .def_readonly("touchdown", &Snapshot::touchdown, "(3) that point [m]")
      .def_readonly("max_penetration", &Snapshot::max_penetration, "deepest penetration into the bottom [m]")
      .def_readonly("contact_energy", &Snapshot::contact_energy, "the bottom's contact springs [J]")
      .def_readonly("strain", &Snapshot::strain, "(n) each link's strain, axial elasticity only (else empty) [-]")
      .def_readonly("stretched_length", &Snapshot::stretched_length, "(n) each link's stretched length [m] (else empty)")
      .def_readonly("far_tension", &Snapshot::far_tension, "(n) the tension at each link's far end [N] (else empty)")
      .def_readonly("slack_links", &Snapshot::slack_links, "links whose stretch carries no tension")
      .def_readonly("bend_radius", &Snapshot::bend_radius,
                    "(n) joint k's bend radius, links k-1 and k (joint 0: against the base's clamp) [m]; inf straight")
      .def_readonly("utilisation", &Snapshot::utilisation,
                    "(n) each link's utilisation: max(tension / max_tension, min_bend_radius / its bend radius) [-]")
      .def_readonly("min_bend_radius", &Snapshot::min_bend_radius, "the smallest link bend radius [m] (inf straight)")
      .def_readonly("min_bend_radius_link", &Snapshot::min_bend_radius_link, "its link (0-based)")
      .def_readonly("max_utilisation", &Snapshot::max_utilisation, "the largest utilisation [-]; 1 = at a limit")
      .def_readonly("max_utilisation_link", &Snapshot::max_utilisation_link, "its link (0-based)")
      .def_readonly("seabed_clearance", &Snapshot::seabed_clearance,
                    "the smallest height of a suspended link end above the bottom [m] (inf without a seabed)");

  py::class_<ModelTerms>(m, "Model", "M q'' + h + G + elastic + D q' = Q at one state (paper coordinates).")
      .def_readonly("coordinates", &ModelTerms::coordinates, "(3n) names, joint_K_elevation/azimuth/torsion")
      .def_readonly("q", &ModelTerms::q, "(3n) [rad]")
      .def_readonly("qd", &ModelTerms::qd, "(3n) [rad/s]")
      .def_readonly("M", &ModelTerms::M, "(3n, 3n) mass matrix [kg m^2]")
      .def_readonly("h", &ModelTerms::h, "(3n) Coriolis and centrifugal terms [N m]")
      .def_readonly("G", &ModelTerms::G, "(3n) generalized weight [N m]")
      .def_readonly("K", &ModelTerms::K, "(3n, 3n) stiffness [N m/rad]")
      .def_readonly("elastic", &ModelTerms::elastic, "(3n) generalized elastic force [N m]")
      .def_readonly("D", &ModelTerms::D, "(3n, 3n) damping [N m s/rad]")
      .def_readonly("kinetic_energy", &ModelTerms::kinetic_energy, "[J]")
      .def_readonly("potential_energy", &ModelTerms::potential_energy, "[J]")
      .def_readonly("elastic_energy", &ModelTerms::elastic_energy, "[J]");

  py::class_<PythonSimulator>(m, "Simulator", "A cable simulator (cable_dynamics::CableSimulator).")
      .def_static("from_file", &fromFile, "path"_a, "overrides"_a = std::vector<std::string>{},
                  "From a YAML config file; overrides like cable_sim --set: ['cable.links=10', ...].")
      .def_static("from_dict", &fromDict, "config"_a, "overrides"_a = std::vector<std::string>{},
                  "From a dict of the config file's keys (checked the same way).")
      .def("step", &PythonSimulator::step, "steps"_a = 1, py::call_guard<py::gil_scoped_release>(),
           "Advances `steps` time steps of dt; RuntimeError when a step fails. Returns the substeps taken (1 per step\n"
           "that was not retried: RK4's start-up pieces of a first step are not counted).")
      .def_property_readonly("time", &PythonSimulator::time, "[s]")
      .def_property_readonly("dt", &PythonSimulator::dt, "[s]")
      .def_property_readonly("links", &PythonSimulator::links, "n (every slot with a winch)")
      .def_property_readonly("coordinates", &PythonSimulator::coordinates, "(3n) coordinate names")
      .def_property_readonly("has_winch", &PythonSimulator::hasWinch)
      .def_property_readonly("energy_drift", &PythonSimulator::energyDrift,
                             "drift of the energy balance as a fraction of the energy scale (RK4; -1 otherwise)")
      .def_property_readonly("retried_steps", &PythonSimulator::retriedSteps)
      .def("stable_time_step", &PythonSimulator::stableTimeStep, "the recommended RK4 dt: half its estimated stability limit, or less where accuracy needs it (a chain released in air) [s]")
      .def("snapshot", &PythonSimulator::snapshot, "The present instant as a Snapshot (numpy arrays).")
      .def(
          "run",
          [](PythonSimulator& s, double duration, double sample, const py::object& on_sample, const std::string& csv) {
            std::function<void(const Snapshot&)> handler;
            if (!on_sample.is_none()) {
              handler = [&on_sample](const Snapshot& snapshot) {
                py::gil_scoped_acquire gil;
                on_sample(snapshot);
              };
            }
            RunOutcome outcome;
            {
              py::gil_scoped_release release;  // the steps run without the GIL; the callback takes it
              outcome = s.run(duration, sample, handler, csv);
            }
            return py::dict("status"_a = outcome.status, "message"_a = outcome.message, "report"_a = outcome.report);
          },
          "duration"_a, "sample"_a = 0.01, "on_sample"_a = py::none(), "csv"_a = std::string(),
          "cable_sim's run from the present instant, written once for both (tools/sampled_run.h): steps for "
          "`duration` [s], calls on_sample(Snapshot) at t = 0, every `sample` [s] and at the end, writes "
          "cable_sim's CSV of those samples to `csv` when given, and judges the run as cable_sim does. Returns "
          "{'status': cable_sim's exit status (0 reliable, 3 diverged, 4 the CSV not written, 5 not reliable), "
          "'message': the reason when not 0, 'report': the lines cable_sim prints after a run}.")
      .def("model", &PythonSimulator::model, "The paper model's matrices at the present state.")
      .def("set_state", &PythonSimulator::setState, "q"_a, "qd"_a, "Paper coordinates (3n) [rad], rates [rad/s].")
      .def("reset", &PythonSimulator::reset, "Back to the configured state and inputs at t = 0.")
      .def(
          "reset_to_equilibrium",
          [](PythonSimulator& s) {
            const StaticSolution solution = s.resetToEquilibrium();
            return py::dict("iterations"_a = solution.iterations, "residual"_a = solution.residual);
          },
          "At rest in the static equilibrium for the present inputs; RuntimeError with the reason if none.")
      .def("set_current", &PythonSimulator::setCurrent, "current"_a, "Uniform current, world axes (z up) [m/s].")
      .def("set_load_target", &PythonSimulator::setLoadTarget, "position"_a, "velocity"_a = kZero,
           "attitude"_a = kIdentity,
           "The ROV's attachment point [m] and velocity [m/s] (world axes from the base's rest position) and "
           "attitude (quaternion x, y, z, w); load.mode anchored or attached.")
      .def("set_base_target", &PythonSimulator::setBaseTarget, "position"_a, "velocity"_a = kZero,
           "attitude"_a = kIdentity, "The vessel's hang-off point, velocity and attitude, as set_load_target.")
      .def("set_body_thrust", &PythonSimulator::setBodyThrust, "force"_a, "torque"_a = kZero,
           "The ROV body's thrust at its origin, in its frame [N], [N m] (load.mode body); held until the next call.")
      .def("set_body_target", &PythonSimulator::setBodyTarget, "position"_a, "attitude"_a = kIdentity,
           "The station keeper's target: the ROV's origin [m] (world axes from the base's rest position) and "
           "attitude (quaternion x, y, z, w); load.mode body.")
      .def(
          "body_pose",
          [](PythonSimulator& s) {
            const BodyPose p = s.bodyPose();
            const Eigen::Vector4d xyzw(p.attitude.x(), p.attitude.y(), p.attitude.z(), p.attitude.w());
            return py::dict("position"_a = p.position, "attitude"_a = xyzw, "velocity"_a = p.velocity,
                            "angular_velocity"_a = p.angular_velocity);
          },
          "The ROV body's origin [m], attitude (x, y, z, w), velocity (world axes) [m/s] and angular velocity "
          "(its frame) [rad/s] (load.mode body).")
      .def("command_winch_speed", &PythonSimulator::commandWinchSpeed, "speed"_a,
           "Winch speed [m/s], + pays out, |speed| <= winch.max_speed.")
      .def("command_winch_length", &PythonSimulator::commandWinchLength, "length"_a,
           "Drive the winch to a deployed length [m] in [winch.min_length, winch.max_length].");
}
