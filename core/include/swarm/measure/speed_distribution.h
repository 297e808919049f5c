#pragma once
/// The particles' speeds against the Maxwell distribution: what a thermal wall or collisions
/// drive a gas towards. Masses may differ: each speed is scaled by sqrt(m / T), and the scaled
/// speeds of a gas at temperature T all follow the one standard Maxwell distribution
/// p(x) = sqrt(2 / pi) x^2 exp(-x^2 / 2).

#include <vector>

#include "swarm/physics/system.h"

namespace swarm {

/// 2/3 of the mean kinetic energy per particle in the frame of the centre of mass (k_B = 1):
/// the temperature of a gas whose velocities are Maxwellian.
double kinetic_temperature(const System& s);

/// The standard Maxwell distribution of x = v sqrt(m / T): density and cumulative probability.
double maxwell_density(double x);
double maxwell_probability_below(double x);

/// Each particle's speed relative to the CM, times sqrt(m / T).
std::vector<double> scaled_speeds(const System& s, double T);

/// Kolmogorov-Smirnov distance: the largest gap between the empirical distribution of the
/// scaled speeds (sorted here) and the Maxwell distribution. For n speeds drawn from the
/// Maxwellian, sqrt(n) D exceeds 1.36 with probability 5 %, 1.63 with probability 1 %.
double maxwell_ks_distance(std::vector<double> scaled);

/// The Kolmogorov distribution's tail, Q(lambda) = 2 sum_k (-1)^(k-1) exp(-2 k^2 lambda^2):
/// the probability that sqrt(n) D exceeds lambda for n draws from the tested distribution, as
/// n grows (Q(1.358) = 0.05, Q(1.628) = 0.01).
double kolmogorov_tail(double lambda);
/// The p-value of the KS distance D of n draws, with Stephens' finite-n correction
/// lambda = (sqrt(n) + 0.12 + 0.11 / sqrt(n)) D. Against a Maxwellian whose T was estimated
/// from the same speeds (check_speeds) the test is conservative: the estimate pulls the
/// Maxwellian towards the data, so a Maxwellian gas is refused less often than p says.
double ks_p_value(double D, std::size_t n);

/// A histogram of scaled speeds in `bins` equal bins over [0, x_max], as probability density
/// (integrates to the fraction of speeds below x_max), beside the Maxwell density at each
/// bin's centre: the plot "speeds against the Maxwellian".
struct SpeedHistogram {
  double x_max = 4;
  std::vector<double> density;  ///< measured, per unit of x
  std::vector<double> maxwell;  ///< maxwell_density at the bin centres
};
SpeedHistogram speed_histogram(const std::vector<double>& scaled, int bins, double x_max = 4);

/// A system's speeds against the Maxwellian at its kinetic temperature: T, the KS distance
/// and the histogram, for the figures and the app's read-out.
struct SpeedCheck {
  double T = 0;
  std::size_t n = 0;
  double ks_distance = 0;  ///< the KS distance; judge it by maxwellian_p (finite-n correct)
  /// ks_p_value of ks_distance: below 0.01, the speeds are not Maxwellian at the 1 % level
  /// (and the wall's T is then not the kinetic T: docs/physics.md, "Wall thermometry").
  double maxwellian_p = 1;
  SpeedHistogram histogram;
};
SpeedCheck check_speeds(const System& s, int bins = 40);

}  // namespace swarm
