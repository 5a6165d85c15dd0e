// Issue 24, the physical limit: the bytes of data a simulator keeps per link, for bench/physical_limit.sh.
// Prints the sizes of the per-link structures of the recursions, and the heap a CableSimulator holds
// (glibc's mallinfo2: every allocation, Eigen's included) after two steps, for a preset at n links.
// The difference between two sizes, divided by the difference in links, is the data per link: an upper
// bound of what one step touches per link (the step reads and writes most of it, some of it once per step).
// Built by bench/CMakeLists.txt (the core from this checkout). Usage: link_bytes CONFIG N [--set key=value ...]
#include <malloc.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cable_dynamics/dynamics/link_block.h"
#include "cable_dynamics/dynamics/stiff_articulated_body.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/simulation/cable_simulator.h"

namespace {
double heapBytes() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: link_bytes CONFIG N [--set key=value ...]\n");
    return 2;
  }
  std::vector<std::string> overrides{"cable.links=" + std::string(argv[2])};
  for (int i = 3; i + 1 < argc; i += 2) overrides.push_back(argv[i + 1]);
  const cable_dynamics::CableParams params = cable_dynamics::loadConfigFile(argv[1], overrides);
  using cable_dynamics::kBlockLanes;
  std::printf("sizeof_stiff_link_terms %zu\n", sizeof(cable_dynamics::StiffLinkTerms));
  std::printf("sizeof_stiff_contact_terms %zu\n", sizeof(cable_dynamics::StiffContactTerms));
  std::printf("link_block_per_link %zu\n", sizeof(cable_dynamics::LinkBlock) / kBlockLanes);
  std::printf("link_constants_per_link %zu\n", sizeof(cable_dynamics::LinkConstants) / kBlockLanes);
  const double before = heapBytes();
  {
    cable_dynamics::CableSimulator sim(params);
    sim.step();
    sim.step();  // the schemes' workspaces are sized by then
    std::printf("heap_bytes %.0f\n", heapBytes() - before);
  }
  return 0;
}
