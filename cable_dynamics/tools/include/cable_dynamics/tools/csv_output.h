#pragma once
/// \file
/// \brief The CSV written by cable_sim: one header naming every column, one row per output time.

#include <ostream>
#include <string>
#include <vector>

#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// Column names: time, the 3n coordinates, their rates (`..._rate`), endK_x/y/z (paper frame, z down),
/// tensionK, top_tension, load_force_x/y/z, base_force_x/y/z, the energies, and base_x/y/z (the base's
/// position, which moves with base.motion or a base pose), the winch's deployed_length, winch_speed,
/// deployed_links, the seabed's contact_energy, grounded_length, touchdown_arc_length (-1: no contact),
/// touchdown_x/y/z (paper frame), max_penetration, and with a seabed seabed_normalK per link [N].
std::vector<std::string> csvColumns(int links, bool seabed = false);

/// Writes the header line.
void writeCsvHeader(std::ostream& out, int links, bool seabed = false);

/// Writes one row; returns false (and writes nothing) when any value is not finite.
bool writeCsvRow(std::ostream& out, const SimulationSnapshot& s);

}  // namespace cable_dynamics
