#pragma once
/// \file
/// \brief DART with joint springs and dampers on the benchmark chain (stiff_step's anchor).

#include <memory>
#include <vector>

#include "chain_spec.h"

namespace bench {

/// Per joint (ball joint k between link k-1, or the base, and link k): spring [N m/rad] and damper
/// [N m s/rad] on the two transverse axes (bending) and about the link (torsion).
struct JointSprings {
  std::vector<double> bending, torsion, bending_damping, torsion_damping;
};

/// A simulator stepped at a fixed dt; construction is not timed, step() is.
class SteppedSystem {
 public:
  virtual ~SteppedSystem() = default;
  virtual void step() = 0;
  virtual bool finite() = 0;  ///< the state is finite (not timed)
};

std::unique_ptr<SteppedSystem> makeDartSprings(const ChainSpec& spec, const JointSprings& springs);

}  // namespace bench
