#include "python_simulator.h"

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>

#include "cable_dynamics/dynamics/paper_model.h"
#include "cable_dynamics/params/format_values.h"
#include "cable_dynamics/tools/csv_output.h"
#include "cable_dynamics/tools/sampled_run.h"

namespace cable_dynamics {
namespace python {
namespace {

/// Python's (x, y, z, w) as a quaternion; the simulator's setter checks it (params/input_gate.h).
Eigen::Quaterniond attitude(const char* name, const Eigen::Vector4d& xyzw) {
  const double norm = xyzw.norm();
  if (!xyzw.allFinite() || norm < 1e-6) {
    throw std::invalid_argument(std::string(name) + " = " + formatVector(xyzw) +
                                ": expected a finite quaternion (x, y, z, w) of non-zero length");
  }
  return Eigen::Quaterniond(xyzw(3), xyzw(0), xyzw(1), xyzw(2)).normalized();
}

}  // namespace

// The simulator's own copy of the parameters, with a winch's drum slots built: what the outputs are sized by.
PythonSimulator::PythonSimulator(const CableParams& params) : params_(ChainModel::withDrumSlots(params)), sim_(params_) {}

long PythonSimulator::step(long steps) {
  if (steps < 1) throw std::invalid_argument("steps = " + std::to_string(steps) + ": expected at least 1");
  long substeps = 0;
  for (long i = 0; i < steps; ++i) {
    const StepReport report = sim_.step();
    if (!report.ok) throw std::runtime_error(report.message);
    substeps += report.substeps;
  }
  return substeps;
}

std::vector<std::string> PythonSimulator::coordinates() const { return coordinateNames(links()); }

Snapshot PythonSimulator::snapshot() {
  sim_.snapshot(snapshot_);
  return toPython(snapshot_);
}

RunOutcome PythonSimulator::run(double duration, double sample, const std::function<void(const Snapshot&)>& on_sample,
                                const std::string& csv) {
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw std::invalid_argument("duration = " + formatNumber(duration) + ": expected a finite number > 0 [s]");
  }
  if (!(sample > 0.0) || !std::isfinite(sample)) {
    throw std::invalid_argument("sample = " + formatNumber(sample) + ": expected a finite number > 0 [s]");
  }
  const bool seabed = params_.seabed.enabled, axial = params_.stretches();
  std::ofstream file;
  std::unique_ptr<CsvWriter> writer;
  if (!csv.empty()) {
    file.open(csv);
    if (!file) throw std::runtime_error("cannot write " + csv);
    writer = std::make_unique<CsvWriter>(file, params_.links, CsvWriter::kDefaultFlushBytes, seabed, axial);
    writer->writeHeader();
  }
  SampledRun sampled(sim_, params_);
  RunOutcome out;
  out.status = sampled.run(
      duration, sample,
      [&](const SimulationSnapshot& s, std::string& why) {
        // cable_sim's check: a row with a non-finite value stops the run (its CSV never holds one).
        if (writer ? !writer->writeRow(s) : !csvRowFinite(s, seabed, axial)) {
          why = nonFiniteOutputReason(s.time);
          return 3;
        }
        if (on_sample) on_sample(toPython(s));
        return 0;
      },
      {}, out.message);
  if (writer && !writer->flush() && out.status == 0) {
    out.status = 4;
    out.message = "cannot write " + csv;
  }
  std::string unreliable;
  out.status = sampled.judge(out.status, out.report, &unreliable);
  if (out.status == 5) out.message = unreliable;
  return out;
}

Snapshot PythonSimulator::toPython(const SimulationSnapshot& s) const {
  Snapshot out;
  out.time = s.time;
  out.q = s.q;
  out.qd = s.qd;
  out.link_ends = s.chain.ends.transpose();
  out.axes = s.axes.transpose();
  out.tension = s.chain.tension;
  out.line_pull = s.line_pull;
  out.load_force = s.chain.load_force;
  out.base_force = s.chain.base_force;
  out.coupling_force = s.chain.coupling_force;
  out.kinetic_energy = s.chain.kinetic_energy;
  out.potential_energy = s.chain.potential_energy;
  out.elastic_energy = s.chain.elastic_energy;
  out.dissipated_energy = s.dissipated_energy;
  out.work_input = s.work_input;
  out.total_energy = s.total_energy;
  out.first_link = s.first_link;
  out.deployed_length = s.deployed_length;
  out.winch_speed = s.winch_speed;
  const SeabedReport& bed = s.chain.seabed;
  out.seabed_force = bed.link_force.transpose();
  out.seabed_normal = bed.normal_force;
  out.grounded_length = bed.grounded_length;
  out.stuck_length = bed.stuck_length;
  out.touchdown_arc_length = bed.touching ? bed.touchdown_arc_length : -1.0;
  out.touchdown = bed.touchdown;
  out.max_penetration = bed.max_penetration;
  out.contact_energy = s.chain.contact_energy;
  out.strain = s.chain.strain;
  out.stretched_length = s.chain.stretch.size() > 0 ? Eigen::VectorXd(sim_.properties().length + s.chain.stretch)
                                                    : Eigen::VectorXd();
  out.far_tension = s.chain.far_tension;
  out.slack_links = s.chain.slack_links;
  const LimitReport& limits = s.chain.limits;
  out.bend_radius = limits.bend_radius;
  out.utilisation = limits.utilisation;
  out.min_bend_radius = limits.min_bend_radius;
  out.min_bend_radius_link = limits.min_bend_radius_link;
  out.max_utilisation = limits.max_utilisation;
  out.max_utilisation_link = limits.max_utilisation_link;
  out.seabed_clearance = limits.seabed_clearance;
  return out;
}

ModelTerms PythonSimulator::model() {
  ModelTerms out;
  out.coordinates = coordinates();
  out.q.resize(3 * links());
  out.qd.resize(3 * links());
  sim_.paperCoordinates(out.q, out.qd);
  const PaperModelTerms t = paperModelAt(sim_.properties(), out.q, out.qd);
  out.M = t.M;
  out.h = t.h;
  out.G = t.G;
  out.K = t.K;
  out.elastic = t.elastic;
  out.D = t.D;
  out.kinetic_energy = t.kinetic_energy;
  out.potential_energy = t.potential_energy;
  out.elastic_energy = t.elastic_energy;
  return out;
}

void PythonSimulator::setState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  sim_.setPaperState(q, qd);  // the core checks the sizes and finiteness, naming them
}

StaticSolution PythonSimulator::resetToEquilibrium() {
  StaticSolution s = sim_.resetToEquilibrium();
  if (!s.converged) throw std::runtime_error("no static equilibrium: " + s.message);
  return s;
}

// The values are checked by the simulator's setters (params/input_gate.h): the same limits and messages
// as the node, live tuning and cable_sim's config.

void PythonSimulator::setCurrent(const Eigen::Vector3d& current) { sim_.setCurrent(current); }

void PythonSimulator::setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                    const Eigen::Vector4d& xyzw) {
  sim_.setLoadTarget(position, velocity, attitude("attitude", xyzw));
}

void PythonSimulator::setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                    const Eigen::Vector4d& xyzw) {
  sim_.setBaseTarget(position, velocity, attitude("attitude", xyzw));
}

void PythonSimulator::setBodyTarget(const Eigen::Vector3d& position, const Eigen::Vector4d& xyzw) {
  sim_.setBodyTarget(position, attitude("attitude", xyzw));
}

void PythonSimulator::commandWinchSpeed(double speed) { sim_.commandWinchSpeed(speed); }

void PythonSimulator::commandWinchLength(double length) { sim_.commandWinchLength(length); }

}  // namespace python
}  // namespace cable_dynamics
