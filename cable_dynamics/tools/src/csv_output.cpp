#include "cable_dynamics/tools/csv_output.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace cable_dynamics {
namespace {

/// The most characters one number takes at 10 significant digits: sign, 10 digits, the point, and an
/// exponent of up to 3 digits with its sign ("-1.234567891e-308": 17).
constexpr std::size_t kMaxNumberChars = 24;

/// Values per row for n links: time, 3n coordinates, 3n rates, 3n ends, n tensions, 26 scalars, with
/// a seabed n normal forces, with axial elasticity n strains and the count of slack links, and last n bend
/// radii, n utilisations and 2 limit scalars.
std::size_t valuesPerRow(int links, bool seabed, bool axial) {
  return 1 + (seabed ? 13 : 12) * static_cast<std::size_t>(links) + 28 + (axial ? links + 1 : 0);
}

/// Calls `visit(value)` for every value of a row, in the columns' order (csvColumns), and
/// `visit_radius(value)` for the bend radii (+inf where straight); stops at the first call that returns
/// false and returns false then.
template <class Visit, class VisitRadius>
bool forEachValue(const SimulationSnapshot& s, bool seabed, bool axial, Visit&& visit, VisitRadius&& visit_radius) {
  const int n = static_cast<int>(s.q.size()) / 3;
  if (!visit(s.time)) return false;
  for (int i = 0; i < 3 * n; ++i) {
    if (!visit(s.q(i))) return false;
  }
  for (int i = 0; i < 3 * n; ++i) {
    if (!visit(s.qd(i))) return false;
  }
  for (int k = 1; k <= n; ++k) {
    for (int c = 0; c < 3; ++c) {
      if (!visit(s.chain.ends(c, k))) return false;
    }
  }
  for (int k = 0; k < n; ++k) {
    if (!visit(s.chain.tension(k))) return false;
  }
  const double scalars[] = {s.line_pull,  // the tension at the top of the deployed cable
                            s.chain.load_force(0), s.chain.load_force(1), s.chain.load_force(2),
                            s.chain.base_force(0), s.chain.base_force(1), s.chain.base_force(2),
                            s.chain.kinetic_energy, s.chain.potential_energy, s.chain.elastic_energy,
                            s.dissipated_energy, s.work_input, s.total_energy,
                            s.chain.ends(0, 0), s.chain.ends(1, 0), s.chain.ends(2, 0),  // the base (it may move)
                            s.deployed_length, s.winch_speed, static_cast<double>(n - s.first_link)};
  for (double x : scalars) {
    if (!visit(x)) return false;
  }
  // The seabed (zeros without one; touchdown_arc_length -1 while nothing touches), paper frame as the ends.
  const SeabedReport& bed = s.chain.seabed;
  const double contact[] = {s.chain.contact_energy, bed.grounded_length, bed.touching ? bed.touchdown_arc_length : -1.0,
                            bed.touchdown.x(), bed.touchdown.y(), bed.touchdown.z(), bed.max_penetration};
  for (double x : contact) {
    if (!visit(x)) return false;
  }
  if (seabed) {
    for (int k = 0; k < n; ++k) {
      if (!visit(k < bed.normal_force.size() ? bed.normal_force(k) : 0.0)) return false;
    }
  }
  if (axial) {
    for (int k = 0; k < n; ++k) {
      if (!visit(k < s.chain.strain.size() ? s.chain.strain(k) : 0.0)) return false;
    }
    if (!visit(static_cast<double>(s.chain.slack_links))) return false;
  }
  // The limits (dynamics/cable_limits.h): each joint's bend radius, each link's utilisation, the smallest
  // radius and the largest utilisation.
  const LimitReport& limits = s.chain.limits;
  for (int k = 0; k < n; ++k) {
    if (!visit_radius(k < limits.bend_radius.size() ? limits.bend_radius(k) : LimitReport::kStraight)) return false;
  }
  for (int k = 0; k < n; ++k) {
    if (!visit(k < limits.utilisation.size() ? limits.utilisation(k) : 0.0)) return false;
  }
  return visit_radius(limits.min_bend_radius) && visit(limits.max_utilisation);
}

}  // namespace

std::vector<std::string> csvColumns(int links, bool seabed, bool axial) {
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
  if (axial) {
    for (int k = 1; k <= links; ++k) c.push_back("strain" + std::to_string(k));
    c.push_back("slack_links");
  }
  for (int k = 1; k <= links; ++k) c.push_back("bend_radius" + std::to_string(k));
  for (int k = 1; k <= links; ++k) c.push_back("utilisation" + std::to_string(k));
  c.push_back("min_bend_radius");
  c.push_back("max_utilisation");
  return c;
}

bool csvRowFinite(const SimulationSnapshot& s, bool seabed, bool axial) {
  // A bend radius may be +inf (a straight joint, written `inf`); nothing else may be non-finite.
  const auto finite = [](double x) { return std::isfinite(x); };
  const auto radius = [](double x) { return std::isfinite(x) || x == LimitReport::kStraight; };
  return forEachValue(s, seabed, axial, finite, radius);
}

CsvWriter::CsvWriter(std::ostream& out, int links, std::size_t flush_bytes, bool seabed, bool axial)
    : out_(out),
      links_(links),
      seabed_(seabed),
      axial_(axial),
      flush_bytes_(flush_bytes),
      row_bytes_(valuesPerRow(links, seabed, axial) * (kMaxNumberChars + 1) + 1),
      buffer_(flush_bytes + row_bytes_) {}

CsvWriter::~CsvWriter() { flush(); }

void CsvWriter::writeHeader() {
  std::string line;
  const std::vector<std::string> columns = csvColumns(links_, seabed_, axial_);
  for (std::size_t i = 0; i < columns.size(); ++i) line += (i ? "," : "") + columns[i];
  line += "\n";
  handOver();
  out_.write(line.data(), static_cast<std::streamsize>(line.size()));
}

bool CsvWriter::writeRow(const SimulationSnapshot& s) {
  if (s.q.size() != 3 * links_) {
    throw std::invalid_argument("CsvWriter: a snapshot of " + std::to_string(s.q.size() / 3) + " links for a CSV of " +
                                std::to_string(links_));
  }
  // Nothing of a row with a non-finite value is written (a bend radius may be +inf: a straight joint,
  // written `inf`): check first, then format (the check is a small fraction of the formatting).
  if (!csvRowFinite(s, seabed_, axial_)) return false;
  bool first = true;
  const auto write = [&](double x) {
    if (!first) append(',');
    first = false;
    append(x);
    return true;
  };
  forEachValue(s, seabed_, axial_, write, write);
  append('\n');
  if (used_ >= flush_bytes_) handOver();
  return true;
}

bool CsvWriter::flush() {
  handOver();
  out_.flush();
  return static_cast<bool>(out_);
}

void CsvWriter::append(double value) {
  // A row never outgrows buffer_: writeRow starts with at most flush_bytes_ used and a row is at most
  // row_bytes_ long.
  char* first = buffer_.data() + used_;
  const std::to_chars_result r =
      std::to_chars(first, first + kMaxNumberChars, value, std::chars_format::general, kCsvSignificantDigits);
  used_ += static_cast<std::size_t>(r.ptr - first);
}

void CsvWriter::handOver() {
  if (used_ == 0) return;
  out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
  used_ = 0;
}

}  // namespace cable_dynamics
