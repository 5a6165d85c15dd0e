// cable_sim's CSV writer against the iostream formatting it replaced: every number as an ostream with
// setprecision(10) writes it (printf's %.10g), the columns in the documented order, nothing of a row with a
// non-finite value, and the same bytes whatever the buffer size.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <cstdlib>
#include <new>
#include <streambuf>

#include <gtest/gtest.h>

#include "cable_dynamics/tools/csv_output.h"

// Counts heap allocations while g_counting is set (this test binary only).
#include "../allocation_counter.h"

namespace cable_dynamics {
namespace {

/// The reference: an ostream at 10 significant digits, as cable_sim wrote its rows before std::to_chars.
std::string streamed(double x) {
  std::ostringstream s;
  s << std::setprecision(10) << x;
  return s.str();
}

/// A snapshot of n links holding `v` in the README's column order, so that a row's values are known
/// independently of the writer: its i-th field must be v[i].
SimulationSnapshot snapshotOf(int n, const std::vector<double>& v) {
  SimulationSnapshot s;
  std::size_t i = 0;
  s.time = v[i++];
  s.q.resize(3 * n);
  s.qd.resize(3 * n);
  s.chain.ends.resize(3, n + 1);
  s.chain.tension.resize(n);
  for (int j = 0; j < 3 * n; ++j) s.q(j) = v[i++];
  for (int j = 0; j < 3 * n; ++j) s.qd(j) = v[i++];
  for (int k = 1; k <= n; ++k) {
    for (int c = 0; c < 3; ++c) s.chain.ends(c, k) = v[i++];
  }
  for (int k = 0; k < n; ++k) s.chain.tension(k) = v[i++];
  s.line_pull = v[i++];
  for (int c = 0; c < 3; ++c) s.chain.load_force(c) = v[i++];
  for (int c = 0; c < 3; ++c) s.chain.base_force(c) = v[i++];
  s.chain.kinetic_energy = v[i++];
  s.chain.potential_energy = v[i++];
  s.chain.elastic_energy = v[i++];
  s.dissipated_energy = v[i++];
  s.work_input = v[i++];
  s.total_energy = v[i++];
  for (int c = 0; c < 3; ++c) s.chain.ends(c, 0) = v[i++];
  s.deployed_length = v[i++];
  s.winch_speed = v[i++];
  // deployed_links = n - first_link
  s.first_link = n - static_cast<int>(v[i++]);
  // The seabed's seven (without the per-link columns, which only a seabed's CSV has).
  s.chain.contact_energy = v[i++];
  s.chain.seabed.grounded_length = v[i++];
  s.chain.seabed.touching = true;  // otherwise the writer puts -1 for the touchdown's arc length
  s.chain.seabed.touchdown_arc_length = v[i++];
  for (int c = 0; c < 3; ++c) s.chain.seabed.touchdown(c) = v[i++];
  s.chain.seabed.max_penetration = v[i++];
  // The limits, last: n bend radii, n utilisations, the smallest radius and the largest utilisation.
  LimitReport& limits = s.chain.limits;
  limits.bend_radius.resize(n);
  limits.utilisation.resize(n);
  for (int k = 0; k < n; ++k) limits.bend_radius(k) = v[i++];
  for (int k = 0; k < n; ++k) limits.utilisation(k) = v[i++];
  limits.min_bend_radius = v[i++];
  limits.max_utilisation = v[i++];
  EXPECT_EQ(i, v.size());
  return s;
}

/// The deployed_links value of a row of values of csvColumns(n) (a count: set it to one): the 19th
/// scalar after time and the 10n per-link values; a row has 12n + 29 values.
double& deployedLinks(std::vector<double>& v) {
  const std::size_t n = (v.size() - 29) / 12;
  return v[10 * n + 19];
}

/// Values that probe the formatting: zeros of both signs, powers of ten around the switch between fixed
/// and exponent notation, rounding at the 10th digit, the extremes of a double, and random magnitudes.
std::vector<double> probeValues(std::size_t count, unsigned seed) {
  std::vector<double> v = {0.0, -0.0, 1.0, -1.0, 0.1, 1e-5, 1e-4, 9.9999999995e-5, 123456789.0, 1234567890.0,
                           12345678901.0, 9999999999.5, 0.30000000000000004, 2.5e-10, -7.77e22,
                           std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::max(),
                           5e-324, 1.7976931348623157e308, 0.5, 1.0 / 3.0, -2.0 / 3.0, 1e15, 1e16, 1e17};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-320, 300);
  while (v.size() < count) v.push_back(mantissa(rng) * std::pow(10.0, exponent(rng)));
  v.resize(count);
  return v;
}

TEST(CsvOutput, NumbersAsTheStreamWroteThem) {
  // 200 rows of n = 100 (1027 values each, about 200,000 numbers), compared with the stream's text.
  const int n = 100;
  const std::size_t per_row = csvColumns(n).size();
  // time, 3n q, 3n rates, 3n ends, n tensions, 26 scalars, then n bend radii, n utilisations and 2 scalars
  ASSERT_EQ(per_row, 1 + 12 * n + 28u);
  for (unsigned seed = 1; seed <= 200; ++seed) {
    std::vector<double> v = probeValues(per_row, seed);
    deployedLinks(v) = 37;  // deployed_links: a count
    std::ostringstream out;
    {
      CsvWriter writer(out, n);
      ASSERT_TRUE(writer.writeRow(snapshotOf(n, v)));
      ASSERT_TRUE(writer.flush());
    }
    std::string expected;
    for (std::size_t i = 0; i < v.size(); ++i) expected += (i ? "," : "") + streamed(v[i]);
    expected += "\n";
    ASSERT_EQ(out.str(), expected) << "seed " << seed;
  }
}

TEST(CsvOutput, HeaderNamesEveryColumn) {
  std::ostringstream out;
  {
    CsvWriter writer(out, 2);
    writer.writeHeader();
  }
  EXPECT_EQ(out.str(),
            "time,joint_1_elevation,joint_1_azimuth,joint_1_torsion,joint_2_elevation,joint_2_azimuth,joint_2_torsion,"
            "joint_1_elevation_rate,joint_1_azimuth_rate,joint_1_torsion_rate,joint_2_elevation_rate,"
            "joint_2_azimuth_rate,joint_2_torsion_rate,end1_x,end1_y,end1_z,end2_x,end2_y,end2_z,tension1,tension2,"
            "top_tension,load_force_x,load_force_y,load_force_z,base_force_x,base_force_y,base_force_z,"
            "kinetic_energy,potential_energy,elastic_energy,dissipated_energy,work_input,total_energy,base_x,base_y,"
            "base_z,deployed_length,winch_speed,deployed_links,contact_energy,grounded_length,touchdown_arc_length,"
            "touchdown_x,touchdown_y,touchdown_z,max_penetration,bend_radius1,bend_radius2,utilisation1,utilisation2,"
            "min_bend_radius,max_utilisation\n");
}

TEST(CsvOutput, AStraightJointsBendRadiusIsWrittenAsInf) {
  // A straight joint's bend radius is +inf (dynamics/cable_limits.h): written `inf`, which numpy's loadtxt
  // and std::strtod read back; NaN and -inf there still refuse the row.
  const int n = 2;
  std::vector<double> v(csvColumns(n).size(), 1.5);
  deployedLinks(v) = 2;
  const std::size_t radius = v.size() - 2 * n - 2, smallest = v.size() - 2;  // bend_radius1, min_bend_radius
  v[radius] = v[smallest] = std::numeric_limits<double>::infinity();
  std::ostringstream out;
  CsvWriter writer(out, n);
  ASSERT_TRUE(writer.writeRow(snapshotOf(n, v)));
  ASSERT_TRUE(writer.flush());
  EXPECT_EQ(out.str().substr(out.str().size() - std::string(",inf,1.5,1.5,1.5,inf,1.5\n").size()), ",inf,1.5,1.5,1.5,inf,1.5\n");
  EXPECT_EQ(std::strtod("inf", nullptr), std::numeric_limits<double>::infinity());
  for (double bad : {std::nan(""), -std::numeric_limits<double>::infinity()}) {
    v[radius] = bad;
    EXPECT_FALSE(writer.writeRow(snapshotOf(n, v))) << bad;
  }
}

TEST(CsvOutput, NonFiniteRowWritesNothing) {
  const int n = 3;
  const std::size_t per_row = csvColumns(n).size();
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    for (std::size_t at : {std::size_t{0}, per_row / 2, per_row - 1}) {
      std::vector<double> v(per_row, 1.5);
      deployedLinks(v) = 3;
      std::ostringstream out;
      CsvWriter writer(out, n);
      ASSERT_TRUE(writer.writeRow(snapshotOf(n, v)));
      v[at] = bad;
      EXPECT_FALSE(writer.writeRow(snapshotOf(n, v))) << "value " << at;
      ASSERT_TRUE(writer.flush());
      const std::string text = out.str();
      EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << "value " << at;  // the good row only
    }
  }
}

TEST(CsvOutput, SameBytesWhateverTheBufferSize) {
  const int n = 20;
  const std::size_t per_row = csvColumns(n).size();
  std::vector<std::string> outputs;
  for (std::size_t flush_bytes : {std::size_t{1}, std::size_t{1000}, std::size_t{1} << 18}) {
    std::ostringstream out;
    {
      CsvWriter writer(out, n, flush_bytes);
      writer.writeHeader();
      for (unsigned row = 0; row < 300; ++row) {
        std::vector<double> v = probeValues(per_row, 1000 + row);
        deployedLinks(v) = 20;
        ASSERT_TRUE(writer.writeRow(snapshotOf(n, v)));
      }
    }  // the destructor flushes
    outputs.push_back(out.str());
  }
  EXPECT_EQ(std::count(outputs[0].begin(), outputs[0].end(), '\n'), 301);
  EXPECT_EQ(outputs[0], outputs[1]);
  EXPECT_EQ(outputs[0], outputs[2]);
}

/// A stream that counts what it is given and keeps nothing (so that the stream itself never allocates).
class CountingSink : public std::streambuf {
 public:
  std::size_t bytes = 0;

 protected:
  std::streamsize xsputn(const char*, std::streamsize n) override {
    bytes += static_cast<std::size_t>(n);
    return n;
  }
  int_type overflow(int_type c) override {
    ++bytes;
    return c;
  }
};

TEST(CsvOutput, NoAllocationPerRow) {
  // Rows of n = 100, through many hand-overs of the buffer (flush_bytes 64 KiB: about every 6 rows).
  const int n = 100;
  std::vector<double> v = probeValues(csvColumns(n).size(), 7);
  deployedLinks(v) = 100;
  const SimulationSnapshot snapshot = snapshotOf(n, v);
  CountingSink sink;
  std::ostream out(&sink);
  CsvWriter writer(out, n, 1 << 16);
  writer.writeHeader();
  g_counting = true;
  for (int row = 0; row < 500; ++row) ASSERT_TRUE(writer.writeRow(snapshot));
  ASSERT_TRUE(writer.flush());
  g_counting = false;
  EXPECT_EQ(g_allocations, 0);
  EXPECT_GT(sink.bytes, 500u * 1027u * 2u);  // the rows went out (at least 2 characters a value)
}

TEST(CsvOutput, WrongSizeNamed) {
  std::ostringstream out;
  CsvWriter writer(out, 4);
  std::vector<double> v(csvColumns(3).size(), 1.0);
  deployedLinks(v) = 3;
  EXPECT_THROW(writer.writeRow(snapshotOf(3, v)), std::invalid_argument);
}

}  // namespace
}  // namespace cable_dynamics

namespace cable_dynamics {
namespace {

TEST(CsvOutput, ASeabedsCsvEndsWithTheNormalForcePerLink) {
  const int n = 3;
  std::vector<double> v(csvColumns(n).size(), 1.5);
  deployedLinks(v) = 3;
  SimulationSnapshot s = snapshotOf(n, v);
  s.chain.seabed.normal_force = Eigen::Vector3d(0.0, 12.5, -0.25);
  std::ostringstream out;
  {
    CsvWriter writer(out, n, CsvWriter::kDefaultFlushBytes, true);
    writer.writeHeader();
    ASSERT_TRUE(writer.writeRow(s));
  }
  const std::string text = out.str();
  const std::string header = text.substr(0, text.find('\n'));
  EXPECT_NE(header.find(",max_penetration,seabed_normal1,seabed_normal2,seabed_normal3,bend_radius1"), std::string::npos);
  const std::string row = text.substr(text.find('\n') + 1);
  // The normal forces, then the limits' 2n + 2 values (all 1.5 here).
  const std::string tail = ",1.5,0,12.5,-0.25,1.5,1.5,1.5,1.5,1.5,1.5,1.5,1.5\n";
  EXPECT_EQ(row.substr(row.size() - tail.size()), tail);
  EXPECT_EQ(csvColumns(n, true).size(), csvColumns(n).size() + n);
}

}  // namespace
}  // namespace cable_dynamics
