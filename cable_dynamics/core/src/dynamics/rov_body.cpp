#include "cable_dynamics/dynamics/rov_body.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "cable_dynamics/dynamics/frames.h"

namespace cable_dynamics {
namespace {

/// C(nu) nu of a symmetric 6x6 mass matrix M (Fossen eq. 6.43): (w x p1, v x p1 + w x p2), p = M nu.
Vector6d coriolisTimes(const Matrix6d& m, const Vector6d& nu) {
  const Vector6d p = m * nu;
  const Eigen::Vector3d v = nu.head<3>(), w = nu.tail<3>(), p1 = p.head<3>(), p2 = p.tail<3>();
  Vector6d out;
  out << w.cross(p1), v.cross(p1) + w.cross(p2);
  return out;
}

}  // namespace

RovBodyConstants RovBodyConstants::make(const LoadParams& load, double fluid_density, double gravity) {
  RovBodyConstants c;
  if (load.mode != LoadMode::kBody) return c;
  const RovBodyParams& p = load.body;
  c.active = true;
  c.mass = load.mass;
  c.center_of_gravity = p.center_of_gravity;
  c.center_of_buoyancy = p.center_of_buoyancy;
  c.attachment = load.attachment;
  // The paper frame is the world turned half a turn about x: paper from body = P R_world, P = diag(1, -1, -1).
  const Eigen::Vector3d& rpy = p.initial_attitude;
  const Eigen::Matrix3d world = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX())).toRotationMatrix();
  const Eigen::Quaterniond start(Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal() * world);
  c.initial_attitude << start.w(), start.x(), start.y(), start.z();
  // M_RB about O (Fossen eq. 3.44): [m I, -m S(r_g); m S(r_g), I_g - m S(r_g)^2].
  const Eigen::Matrix3d sg = crossMatrix(p.center_of_gravity);
  c.rigid_mass.topLeftCorner<3, 3>() = load.mass * Eigen::Matrix3d::Identity();
  c.rigid_mass.topRightCorner<3, 3>() = -load.mass * sg;
  c.rigid_mass.bottomLeftCorner<3, 3>() = load.mass * sg;
  c.rigid_mass.bottomRightCorner<3, 3>() = p.inertia - load.mass * sg * sg;
  // The added mass and the damping are the water's: in air (fluid.density 0) the body has neither, as
  // the links have no drag there.
  const bool in_water = fluid_density > 0.0;
  c.added_mass = in_water ? p.added_mass : Matrix6d::Zero();
  c.linear_damping = in_water ? p.linear_damping : Vector6d::Zero();
  c.quadratic_damping = in_water ? p.quadratic_damping : Vector6d::Zero();
  c.weight = load.mass * gravity;
  c.buoyancy = fluid_density * load.volume * gravity;
  // About P: M_P = H^T M H, H = [I S(r); 0 I].
  Matrix6d h = Matrix6d::Identity();
  h.topRightCorner<3, 3>() = crossMatrix(load.attachment);
  const Matrix6d mp = h.transpose() * (c.rigid_mass + c.added_mass) * h;
  const Eigen::Matrix3d a = mp.topLeftCorner<3, 3>(), b = mp.topRightCorner<3, 3>(), cc = mp.bottomRightCorner<3, 3>();
  c.c_inverse = cc.llt().solve(Eigen::Matrix3d::Identity());
  c.b_c_inverse = b * c.c_inverse;
  c.b_transpose = b.transpose();
  c.schur = a - c.b_c_inverse * c.b_transpose;
  c.schur = 0.5 * (c.schur + c.schur.transpose()).eval();  // symmetric to round-off: the recursions read one half
  return c;
}

Eigen::Matrix3d rotationOf(const Eigen::Vector4d& q) {
  const double w = q(0), x = q(1), y = q(2), z = q(3);
  Eigen::Matrix3d r;
  r << 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),
      2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),
      2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y);
  return r;
}

Eigen::Vector4d attitudeRate(const Eigen::Vector4d& q, const Eigen::Vector3d& w) {
  const Eigen::Vector3d v = q.tail<3>();
  Eigen::Vector4d rate;
  rate(0) = -0.5 * v.dot(w);
  rate.tail<3>() = 0.5 * (q(0) * w + v.cross(w));
  return rate;
}

Eigen::Vector4d turnedAttitude(const Eigen::Vector4d& q, const Eigen::Vector3d& turn) {
  const double angle = turn.norm();
  const double half_sine = angle > 1e-12 ? std::sin(0.5 * angle) / angle : 0.5;  // sin(a/2)/a
  const double w = std::cos(0.5 * angle);
  const Eigen::Vector3d e = half_sine * turn, v = q.tail<3>();
  Eigen::Vector4d out;  // q (w, e): (q0 w - v.e, q0 e + w v + v x e)
  out(0) = q(0) * w - v.dot(e);
  out.tail<3>() = q(0) * e + w * v + v.cross(e);
  return out / out.norm();
}

void computeRovBodyTerms(const RovBodyConstants& body, const Eigen::Vector4d& attitude, const Eigen::Vector3d& omega,
                         const Eigen::Vector3d& tip_velocity, const Eigen::Vector3d& current, const Vector6d& thrust,
                         RovBodyTerms& t) {
  t.attitude = attitude / attitude.norm();  // a stage's quaternion is unit only to the step's order
  t.rotation = rotationOf(t.attitude);
  const Eigen::Matrix3d& rt = t.rotation;
  t.omega = omega;
  t.attach_velocity = rt.transpose() * tip_velocity;
  t.velocity << t.attach_velocity + body.attachment.cross(omega), omega;  // v_O = v_P + r x w
  t.thrust = thrust;
  Vector6d relative = t.velocity;
  const Eigen::Vector3d current_body = rt.transpose() * current;
  relative.head<3>() -= current_body;
  // The fluid: added mass's Coriolis and the current turning in the body frame, damping.
  Vector6d turning = Vector6d::Zero();
  turning.head<3>() = omega.cross(current_body);
  const Vector6d damping =
      (body.linear_damping.array() + body.quadratic_damping.array() * relative.array().abs()) * relative.array();
  t.fluid = -coriolisTimes(body.added_mass, relative) - body.added_mass * turning - damping;
  // Weight at the centre of gravity, buoyancy at the centre of buoyancy (paper z down: weight along +z).
  const Eigen::Vector3d down = rt.transpose().col(2);  // the paper frame's z in the body frame
  Vector6d restoring;
  restoring << (body.weight - body.buoyancy) * down,
      body.center_of_gravity.cross(body.weight * down) - body.center_of_buoyancy.cross(body.buoyancy * down);
  const Vector6d f_o = thrust + restoring + t.fluid - coriolisTimes(body.rigid_mass, t.velocity);
  // About P: the moment less r x f.
  t.force << f_o.head<3>(), f_o.tail<3>() - body.attachment.cross(f_o.head<3>());
  const Eigen::Vector3d centripetal = omega.cross(t.attach_velocity);  // a_P = R^T a - w x v_P
  t.tip_mass = rt * body.schur * rt.transpose();
  t.tip_bias = rt * (body.b_c_inverse * t.force.tail<3>() - t.force.head<3>() - body.schur * centripetal);
}

Eigen::Vector3d finishRovBody(const RovBodyConstants& body, const Eigen::Vector3d& tip_acceleration, RovBodyTerms& t) {
  const Eigen::Vector3d a_p = t.rotation.transpose() * tip_acceleration - t.omega.cross(t.attach_velocity);
  const Eigen::Vector3d w_dot = body.c_inverse * (t.force.tail<3>() - body.b_transpose * a_p);
  t.acceleration << a_p + body.attachment.cross(w_dot), w_dot;  // nu_O' = H nu_P'
  t.thrust_power = t.thrust.dot(t.velocity);
  t.fluid_power = (t.fluid - body.added_mass * t.acceleration).dot(t.velocity);
  return t.tip_mass * tip_acceleration + t.tip_bias;
}

Eigen::Vector3d rovBodyOrigin(const RovBodyConstants& body, const Eigen::Matrix3d& rotation,
                              const Eigen::Vector3d& tip_position) {
  return tip_position - rotation * body.attachment;
}

void rovBodyEnergy(const RovBodyConstants& body, const RovBodyTerms& t, const Eigen::Vector3d& tip_position,
                   double& kinetic, double& potential) {
  kinetic = 0.5 * t.velocity.dot(body.rigid_mass * t.velocity);
  const Eigen::Vector3d origin = rovBodyOrigin(body, t.rotation, tip_position);
  const double z_g = (origin + t.rotation * body.center_of_gravity).z();
  const double z_b = (origin + t.rotation * body.center_of_buoyancy).z();
  potential = -body.weight * z_g + body.buoyancy * z_b;
}

}  // namespace cable_dynamics
