#include "cable_dynamics/params/states.h"

#include <cmath>
#include <random>

namespace cable_dynamics {

void randomState(int links, unsigned seed, Eigen::VectorXd& q, Eigen::VectorXd& qd) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> elevation(0.2, 1.3), angle(-M_PI, M_PI), rate(-1.0, 1.0);
  q.resize(3 * links);
  qd.resize(3 * links);
  for (int k = 0; k < links; ++k) {
    q(3 * k) = elevation(rng);
    q(3 * k + 1) = angle(rng);
    q(3 * k + 2) = angle(rng);
  }
  for (int i = 0; i < 3 * links; ++i) qd(i) = rate(rng);
}

void initialState(const CableParams& params, Eigen::VectorXd& q, Eigen::VectorXd& qd) {
  const int n = params.links;
  q.resize(3 * n);
  qd = Eigen::VectorXd::Zero(3 * n);
  for (int k = 0; k < n; ++k) {
    q(3 * k) = params.initial.elevation[k];
    q(3 * k + 1) = params.initial.azimuth[k];
    q(3 * k + 2) = params.initial.torsion[k];
  }
}

}  // namespace cable_dynamics
