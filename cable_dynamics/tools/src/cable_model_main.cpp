// cable_model: prints the automatically generated dynamic model at one state as JSON.
// Usage: cable_model --config FILE [--set key.path=value ...] [--q v1,...,v3n --qd v1,...,v3n | --random-state SEED]
#include <iostream>

#include "cable_dynamics/tools/cable_model_app.h"

int main(int argc, char** argv) { return cable_dynamics::runCableModel(argc, argv, std::cout, std::cerr); }
