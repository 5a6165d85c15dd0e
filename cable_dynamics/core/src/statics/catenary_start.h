#pragma once
// The statics' start for a limp uniform line anchored exactly: the elastic catenary between the base and
// the anchor, with a grounded part on a flat frictionless bed at the anchor's depth (Irvine, Cable
// Structures, 1981, ch. 2; the bench's reference, bench/moordyn/moordyn_bench.cpp). From it Newton starts
// with the bed at full strength, one discretization away from its answer, where the general start (the
// line hanging through the bed, then the bed's contact ramped up from 1e-4) took 26-29 iterations on
// MoorDyn's chains. Internal to the statics.

#include <Eigen/Core>

#include "static_equations.h"

namespace cable_dynamics {
namespace statics {

/// The catenary's shape in its plane for the unstretched arc sigma [m] measured from the anchor, and
/// its tension there.
struct CatenaryPoint {
  double along = 0.0;   ///< horizontal distance from the anchor towards the base [m]
  double height = 0.0;  ///< height above the anchor [m]
  double tension = 0.0; ///< [N]
};

/// The elastic catenary of a line of unstretched length L [m], submerged weight w [N/m] and axial
/// stiffness EA [N] (infinity: inextensible) from an anchor to a point `span` [m] away horizontally and
/// `rise` [m] above it; where `grounded` the part the line would hang below the anchor lies on a
/// frictionless bed through the anchor (else it hangs). Solves for the horizontal tension H and the
/// vertical one at the top by Newton on the two closure equations.
class ElasticCatenary {
 public:
  /// False when no shape was found (a span beyond the stretched length, a degenerate line).
  bool solve(double length, double weight, double axial_stiffness, double span, double rise, bool grounded);

  CatenaryPoint at(double sigma) const;
  double horizontalTension() const { return h_; }  ///< H [N]
  /// The vertical tension at the anchor [N] (negative: the line would hang below it; 0 when grounded).
  double anchorVertical() const { return grounded_length_ > 0.0 ? 0.0 : top_vertical_ - w_ * length_; }
  double groundedLength() const { return grounded_length_; }  ///< [m], unstretched

 private:
  /// The top's offset from the anchor (horizontal, vertical) for H and the top's vertical tension V [N].
  Eigen::Vector2d top(double h, double v) const;

  double length_ = 0.0, w_ = 0.0, compliance_ = 0.0;  // [m], [N/m], 1 / EA [1/N]
  bool grounded_ = false;
  double h_ = 0.0, top_vertical_ = 0.0, grounded_length_ = 0.0;
};

/// For an exactly anchored, limp (no bend springs), uniform (one weight per length and one EA over the
/// deployed links), attachment-free line in still water whose anchor sits on a flat bed: the catenary's
/// link axes into `s` (base ends and forces by forcesForAxes), each link's stretch under its far end's
/// tension into `stretch` (n, model indices; zero where a link does not stretch), and the statics' hold's
/// target that carries the catenary's pull on the anchor into `target` [m] (the anchor moved by that pull
/// over staticHoldStiffness). False where the start does not apply; nothing is written then.
bool catenaryStart(const ChainModel& model, const ChainDeployment& deployed, const CurrentField& current,
                   const StaticProblem& problem, StaticState& s, Eigen::VectorXd& stretch, Eigen::Vector3d& target);

}  // namespace statics
}  // namespace cable_dynamics
