#pragma once
/// \file
/// \brief Sizes an attached load's coupling for the pose exchange it runs over (docs/ROV_COUPLING.md): the
///        spring and damper between the cable's tip and the ROV's attachment point are felt by the ROV one
///        exchange late, so they must be soft enough for the lightest ROV the node is to hold at the delay
///        the exchange has. ROS-light: stamps in, stiffness and damping out.

#include <array>

#include <ros/time.h>

namespace cable_dynamics {

class CouplingSizer {
 public:
  /// The delay's share of the ROV's inertia the coupling may use: k <= kSpring m / tau^2 and
  /// c <= kDamper m / tau (tau the loop delay [s], m the lightest ROV [kg]). Chosen from the pose-client runs
  /// of test/node/test_rov_client.py (docs/ROV_COUPLING.md gives the figures): at tau = 20 ms a 5 kg ROV
  /// diverged at k = 20 kN/m (k tau^2 / m = 1.6) and held at 5 kN/m (0.4).
  static constexpr double kSpring = 0.25;
  static constexpr double kDamper = 0.5;
  /// A new size is applied only when the measured delay exceeds the one the size in force was made for by
  /// more than kSoften (a softer coupling), or falls below it by more than kStiffen. Before resizes were
  /// bumpless (CableSimulator::retune now keeps the spring's force through a new stiffness), each changed
  /// the force at the offset it held (40 N at 1.3 cm, k 3 kN/m) in one step, and a size chasing the
  /// stamps' jitter kicked the tip's mode on the coupling over and over (the force swung 30-52 N about its
  /// 40.7 N at 10 % hysteresis); the hysteresis stays so that the size does not chase the jitter.
  static constexpr double kSoften = 0.25;
  static constexpr double kStiffen = 0.5;
  /// The exchange period is this quantile of the last kIntervals stamp intervals: the slow exchanges, not
  /// the typical one, are what the coupling must survive (a loaded machine's client runs late in bursts).
  static constexpr double kQuantile = 0.9;

  /// `stiffness` [N/m] and `damping` [N s/m]: the configured coupling, never exceeded; `min_mass` [kg]: the
  /// lightest ROV to hold (ros.min_rov_mass); `cycle_period` [s]: the node's own period (1 / ros.rate),
  /// part of the delay, and the exchange period assumed until poses have measured it.
  CouplingSizer(double stiffness, double damping, double min_mass, double cycle_period);

  /// The configured coupling changed (live tuning): the new caps.
  void setConfigured(double stiffness, double damping);
  /// An accepted pose's stamp. Returns true when the size changed beyond the hysteresis (apply it).
  bool observe(const ros::Time& stamp);
  /// Forgets the stream (a reset): the exchange period is measured afresh.
  void forgetStream();

  double stiffness() const { return stiffness_; }     ///< in force [N/m]
  double damping() const { return damping_; }         ///< in force [N s/m]
  double exchangePeriod() const { return exchange_period_; }  ///< measured (kQuantile of the last intervals) [s]
  double delay() const { return exchange_period_ + cycle_period_; }  ///< the loop's delay tau [s]

 private:
  /// The coupling for the delay `tau` [s]: the configured one, or softer.
  void sizeFor(double tau, double& stiffness, double& damping) const;
  /// The size for the present delay; true when it moved beyond the hysteresis from the one in force.
  bool resize();

  double configured_stiffness_, configured_damping_, min_mass_, cycle_period_;
  double exchange_period_;
  double sized_delay_;  ///< the delay the size in force was made for [s]
  double stiffness_ = 0.0, damping_ = 0.0;
  static constexpr int kIntervals = 31;  ///< the quantile of this many stamp intervals
  std::array<double, kIntervals> intervals_{};
  int count_ = 0;
  ros::Time last_stamp_;
};

}  // namespace cable_dynamics
