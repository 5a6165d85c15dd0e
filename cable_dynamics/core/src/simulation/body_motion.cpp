#include "cable_dynamics/simulation/body_motion.h"

#include <cmath>

#include "cable_dynamics/dynamics/frames.h"

namespace cable_dynamics {

void attitudeAt(const MotionParams& m, double t, Eigen::Matrix3d& rotation, Eigen::Matrix3d& rate,
                Eigen::Matrix3d& acceleration) {
  const double w = 2.0 * M_PI / m.period;
  double angle[3], speed[3], accel[3];  // roll, pitch, yaw and their rates
  for (int i = 0; i < 3; ++i) {
    const double phase = w * t + m.attitude_phase(i), a = m.attitude_amplitude(i);
    angle[i] = a * std::sin(phase);
    speed[i] = a * w * std::cos(phase);
    accel[i] = -a * w * w * std::sin(phase);
  }
  // R = A B C with A = Rz(yaw), B = Ry(pitch), C = Rx(roll); each factor's derivative is K X, K the
  // cross-product matrix of its axis, and its second derivative K^2 X.
  // d/dq of a rotation by q about the unit axis a is [a]x R.
  const Eigen::Matrix3d kx = crossMatrix(Eigen::Vector3d::UnitX()), ky = crossMatrix(Eigen::Vector3d::UnitY()),
                        kz = crossMatrix(Eigen::Vector3d::UnitZ());
  const Eigen::Matrix3d A = Eigen::AngleAxisd(angle[2], Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d B = Eigen::AngleAxisd(angle[1], Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d C = Eigen::AngleAxisd(angle[0], Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d dA = kz * A, dB = ky * B, dC = kx * C;
  const Eigen::Matrix3d ddA = kz * dA, ddB = ky * dB, ddC = kx * dC;
  const double yaw = speed[2], pitch = speed[1], roll = speed[0];
  rotation = A * B * C;
  rate = dA * B * C * yaw + A * dB * C * pitch + A * B * dC * roll;
  acceleration = ddA * B * C * (yaw * yaw) + A * ddB * C * (pitch * pitch) + A * B * ddC * (roll * roll) +
                 2.0 * (dA * dB * C * (yaw * pitch) + dA * B * dC * (yaw * roll) + A * dB * dC * (pitch * roll)) +
                 dA * B * C * accel[2] + A * dB * C * accel[1] + A * B * dC * accel[0];
}

void bodyPointAt(const MotionParams& m, const Eigen::Vector3d& offset, double t, Eigen::Vector3d& p,
                 Eigen::Vector3d& v, Eigen::Vector3d& a) {
  if (m.amplitude.isZero()) {
    // No oscillation: the same values without the sine and cosine, which were a twentieth of a short
    // chain's RK4 step (five calls per step at a base that does not move).
    p = m.offset + m.velocity * t;
    v = m.velocity;
    a.setZero();
  } else {
    const double w = 2.0 * M_PI / m.period, angle = w * t + m.phase;
    p = m.offset + m.amplitude * std::sin(angle) + m.velocity * t;
    v = m.amplitude * (w * std::cos(angle)) + m.velocity;
    a = m.amplitude * (-w * w * std::sin(angle));
  }
  if (m.attitude_amplitude.isZero() || offset.isZero()) return;
  Eigen::Matrix3d rotation, rate, acceleration;
  attitudeAt(m, t, rotation, rate, acceleration);
  p += (rotation - Eigen::Matrix3d::Identity()) * offset;
  v += rate * offset;
  a += acceleration * offset;
}

BodyWrench wrenchAboutOrigin(const Eigen::Vector3d& force, const Eigen::Quaterniond& attitude,
                             const Eigen::Vector3d& offset) {
  BodyWrench w;
  w.force = force;
  w.moment = (attitude * offset).cross(force);
  w.force_body = attitude.conjugate() * force;
  w.moment_body = offset.cross(w.force_body);
  return w;
}

}  // namespace cable_dynamics
