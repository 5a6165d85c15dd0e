#include "cable_dynamics/tools/csv_output.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace cable_dynamics {
namespace {

std::vector<double> rowValues(const SimulationSnapshot& s) {
  const int n = static_cast<int>(s.q.size()) / 3;
  std::vector<double> v;
  v.reserve(8 * n + 16);
  v.push_back(s.time);
  for (int i = 0; i < 3 * n; ++i) v.push_back(s.q(i));
  for (int i = 0; i < 3 * n; ++i) v.push_back(s.qd(i));
  for (int k = 1; k <= n; ++k) {
    for (int c = 0; c < 3; ++c) v.push_back(s.chain.ends(c, k));
  }
  for (int k = 0; k < n; ++k) v.push_back(s.chain.tension(k));
  v.push_back(s.line_pull);  // the tension at the top of the deployed cable
  for (int c = 0; c < 3; ++c) v.push_back(s.chain.load_force(c));
  for (int c = 0; c < 3; ++c) v.push_back(s.chain.base_force(c));
  v.push_back(s.chain.kinetic_energy);
  v.push_back(s.chain.potential_energy);
  v.push_back(s.chain.elastic_energy);
  v.push_back(s.dissipated_energy);
  v.push_back(s.work_input);
  v.push_back(s.total_energy);
  for (int c = 0; c < 3; ++c) v.push_back(s.chain.ends(c, 0));  // the base (it may move)
  v.push_back(s.deployed_length);
  v.push_back(s.winch_speed);
  v.push_back(static_cast<double>(n - s.first_link));
  // The seabed (zeros without one; touchdown_arc_length -1 while nothing touches), paper frame as the ends.
  const SeabedReport& bed = s.chain.seabed;
  for (double x : {s.chain.contact_energy, bed.grounded_length, bed.touching ? bed.touchdown_arc_length : -1.0,
                   bed.touchdown.x(), bed.touchdown.y(), bed.touchdown.z(), bed.max_penetration}) {
    v.push_back(x);
  }
  for (int k = 0; k < bed.normal_force.size(); ++k) v.push_back(bed.normal_force(k));
  return v;
}

}  // namespace

std::vector<std::string> csvColumns(int links, bool seabed) {
  std::vector<std::string> c{"time"};
  for (int i = 0; i < 3 * links; ++i) c.push_back(coordinateName(i));
  for (int i = 0; i < 3 * links; ++i) c.push_back(coordinateName(i) + "_rate");
  for (int k = 1; k <= links; ++k) {
    for (const char* axis : {"_x", "_y", "_z"}) c.push_back("end" + std::to_string(k) + axis);
  }
  for (int k = 1; k <= links; ++k) c.push_back("tension" + std::to_string(k));
  for (const char* name : {"top_tension", "load_force_x", "load_force_y", "load_force_z", "base_force_x",
                           "base_force_y", "base_force_z", "kinetic_energy", "potential_energy", "elastic_energy",
                           "dissipated_energy", "work_input", "total_energy", "base_x", "base_y", "base_z",
                           "deployed_length", "winch_speed", "deployed_links", "contact_energy", "grounded_length",
                           "touchdown_arc_length", "touchdown_x", "touchdown_y", "touchdown_z", "max_penetration"}) {
    c.push_back(name);
  }
  if (seabed) {
    for (int k = 1; k <= links; ++k) c.push_back("seabed_normal" + std::to_string(k));
  }
  return c;
}

void writeCsvHeader(std::ostream& out, int links, bool seabed) {
  const std::vector<std::string> columns = csvColumns(links, seabed);
  for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
  out << "\n";
}

bool writeCsvRow(std::ostream& out, const SimulationSnapshot& s) {
  const std::vector<double> v = rowValues(s);
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  std::ostringstream line;
  line << std::setprecision(10);
  for (std::size_t i = 0; i < v.size(); ++i) line << (i ? "," : "") << v[i];
  out << line.str() << "\n";
  return true;
}

}  // namespace cable_dynamics
