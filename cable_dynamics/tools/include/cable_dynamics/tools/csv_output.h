#pragma once
/// \file
/// \brief The CSV written by cable_sim: one header naming every column, one row per output time.
///
/// Numbers are written with 10 significant digits in the shortest of fixed and exponent notation (printf's
/// `%.10g`, what an ostream with setprecision(10) writes), by std::to_chars into one buffer that goes to
/// the stream in large blocks: no iostream formatting per value and no allocation per row.

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// Significant digits of every number in the CSV (the tests that read it back rely on this).
constexpr int kCsvSignificantDigits = 10;

/// Column names: time, the 3n coordinates, their rates (`..._rate`), endK_x/y/z (paper frame, z down),
/// tensionK, top_tension, load_force_x/y/z, base_force_x/y/z, the energies, base_x/y/z (the base's
/// position, which moves with base.motion or a base pose), deployed_length, winch_speed, deployed_links,
/// the seabed's contact_energy, grounded_length, touchdown_arc_length (-1: no contact), touchdown_x/y/z
/// (paper frame), max_penetration, with a seabed seabed_normalK per link [N], with axial elasticity
/// strainK per link [-] (its stretched length is l_K (1 + strainK)) and slack_links (a count), and last
/// the limits (dynamics/cable_limits.h): bend_radiusK per joint [m] (`inf` where straight), utilisationK
/// per link [-], min_bend_radius [m] and max_utilisation [-].
std::vector<std::string> csvColumns(int links, bool seabed = false, bool axial = false);

/// Whether every value of the row cable_sim's CSV would write for `s` is finite, a bend radius's +inf (a
/// straight joint) allowed (CsvWriter::writeRow writes nothing and returns false otherwise): the same check
/// for a run that writes no CSV (Simulator.run).
bool csvRowFinite(const SimulationSnapshot& s, bool seabed = false, bool axial = false);

/// Writes cable_sim's CSV to a stream: the header, then rows formatted into a buffer sized once for
/// `links` and handed to the stream whenever it holds more than `flush_bytes`, and at flush().
class CsvWriter {
 public:
  /// \param[in] out    the stream written to; it must outlive the writer
  /// \param[in] links  n, the number of link slots of every row
  /// \param[in] seabed with the per-link seabed_normalK columns
  /// \param[in] axial with the strainK and slack_links columns
  CsvWriter(std::ostream& out, int links, std::size_t flush_bytes = kDefaultFlushBytes, bool seabed = false,
            bool axial = false);
  static constexpr std::size_t kDefaultFlushBytes = 1 << 18;
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  /// Flushes what is buffered (errors then go unreported: call flush() to see them).
  ~CsvWriter();

  /// The header line (buffered).
  void writeHeader();
  /// One row, buffered; returns false and buffers nothing when any value is not finite. The snapshot must
  /// have `links` slots.
  bool writeRow(const SimulationSnapshot& s);
  /// Hands the buffer to the stream and flushes it; false when the stream failed.
  bool flush();

 private:
  void append(double value);
  void append(char c) { buffer_[used_++] = c; }
  void handOver();

  std::ostream& out_;
  int links_;
  bool seabed_;
  bool axial_;
  std::size_t flush_bytes_;
  std::size_t row_bytes_;     ///< the longest row's characters, newline included
  std::vector<char> buffer_;  ///< flush_bytes_ + row_bytes_, allocated once
  std::size_t used_ = 0;
};

}  // namespace cable_dynamics
