// cable_sim: simulates the cable offline (no roscore) and writes a CSV, optionally a plot and a rosbag.
// Usage: cable_sim --config FILE [--set key.path=value ...] --duration S --output run.csv [--plot run.png]
//        [--bag run.bag]
#include <iostream>

#include "cable_dynamics/tools/bag_recorder.h"
#include "cable_dynamics/tools/cable_sim_app.h"

int main(int argc, char** argv) {
  return cable_dynamics::runCableSim(argc, argv, std::cout, std::cerr, cable_dynamics::bagRecorderFactory());
}
