#include "cable_dynamics/dynamics/paper_coordinates.h"

#include <cmath>

#include "cable_dynamics/dynamics/paper_model.h"

namespace cable_dynamics {
namespace {

const Eigen::Vector3d kDown = Eigen::Vector3d::UnitZ();

inline double wrapToPi(double a) { return std::atan2(std::sin(a), std::cos(a)); }

}  // namespace

void paperCoordinates(int links, const AzimuthTracker& azimuths, const Eigen::VectorXd& x, Eigen::VectorXd& q,
                      Eigen::VectorXd& qd) {
  double psi_prev = 0.0, phi_prev = 0.0, psi_rate_prev = 0.0, phi_rate_prev = 0.0;
  for (int k = 0; k < links; ++k) {
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k)).normalized();
    const Eigen::Vector3d omega = x.segment<3>(StateLayout::omega(k));
    const double horizontal = std::hypot(axis.x(), axis.y());
    const double te = std::atan2(horizontal, axis.z());
    const double reference = azimuths.reference(k);
    double psi = reference;
    if (horizontal > kVerticalSine) psi += wrapToPi(std::atan2(axis.x(), axis.y()) - reference);
    const double phi = x(StateLayout::twist(k)) - psi;
    Eigen::Vector3d nvec, evec;
    eulerAxes(te, psi, nvec, evec);
    const double te_rate = -omega.dot(nvec);
    // Straight down, the rotation about the vertical is all counted as torsion (only psi + phi is defined).
    const double psi_rate = horizontal > kVerticalSine ? omega.dot(evec) / std::sin(te) : 0.0;
    const double phi_rate = -omega.dot(axis) - psi_rate * std::cos(te);
    q.segment<3>(3 * k) << te, psi - psi_prev, phi - phi_prev;
    qd.segment<3>(3 * k) << te_rate, psi_rate - psi_rate_prev, phi_rate - phi_rate_prev;
    psi_prev = psi;
    phi_prev = phi;
    psi_rate_prev = psi_rate;
    phi_rate_prev = phi_rate;
  }
}

void stateFromPaper(int links, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& x) {
  x.setZero(StateLayout::size(links));
  double psi = 0.0, phi = 0.0, psi_rate = 0.0, phi_rate = 0.0;
  for (int k = 0; k < links; ++k) {
    psi += q(3 * k + 1);
    phi += q(3 * k + 2);
    psi_rate += qd(3 * k + 1);
    phi_rate += qd(3 * k + 2);
    const double te = q(3 * k), te_rate = qd(3 * k);
    const Eigen::Vector3d axis = linkAxis(te, psi);
    Eigen::Vector3d nvec, evec;
    eulerAxes(te, psi, nvec, evec);
    x.segment<3>(StateLayout::axis(k)) = axis;
    x(StateLayout::twist(k)) = psi + phi;
    x.segment<3>(StateLayout::omega(k)) = -psi_rate * kDown - te_rate * nvec - phi_rate * axis;
  }
}

void followAzimuths(int links, const Eigen::VectorXd& x, AzimuthTracker& azimuths, int first) {
  for (int k = first; k < links; ++k) {
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k));
    // Straight down the azimuth is undefined: keep the previous one (as paperCoordinates() does).
    const double horizontal_squared = axis.x() * axis.x() + axis.y() * axis.y();
    if (horizontal_squared > kVerticalSine * kVerticalSine * axis.squaredNorm()) azimuths.follow(k, axis.x(), axis.y());
  }
}

}  // namespace cable_dynamics
