#include "swarm/measure/speed_distribution.h"

#include <algorithm>
#include <cmath>

#include "swarm/physics/diagnostics.h"

namespace swarm {

double kinetic_temperature(const System& s) {
  if (s.particles.empty()) return 0;
  const Vec3 V = cm_velocity(s);
  double twice_kinetic = 0;
  for (const Particle& p : s.particles) twice_kinetic += p.m * (p.v - V).squaredNorm();
  return twice_kinetic / (3.0 * double(s.particles.size()));
}

double maxwell_density(double x) {
  return x <= 0 ? 0 : std::sqrt(2 / M_PI) * x * x * std::exp(-0.5 * x * x);
}

double maxwell_probability_below(double x) {
  if (x <= 0) return 0;
  return std::erf(x / std::sqrt(2.0)) - std::sqrt(2 / M_PI) * x * std::exp(-0.5 * x * x);
}

std::vector<double> scaled_speeds(const System& s, double T) {
  const Vec3 V = cm_velocity(s);
  std::vector<double> out;
  out.reserve(s.particles.size());
  for (const Particle& p : s.particles) out.push_back((p.v - V).norm() * std::sqrt(p.m / T));
  return out;
}

double maxwell_ks_distance(std::vector<double> scaled) {
  std::sort(scaled.begin(), scaled.end());
  const double n = double(scaled.size());
  double D = 0;
  for (std::size_t i = 0; i < scaled.size(); ++i) {
    const double F = maxwell_probability_below(scaled[i]);
    D = std::max({D, double(i + 1) / n - F, F - double(i) / n});
  }
  return D;
}

double kolmogorov_tail(double lambda) {
  // Below 0.2 the series converges slowly and Q is 1 to 1e-9.
  if (lambda < 0.2) return 1;
  double sum = 0, sign = 1;
  for (int k = 1; k <= 100; ++k) {
    const double term = std::exp(-2.0 * k * k * lambda * lambda);
    sum += sign * term;
    if (term < 1e-16 * sum) break;
    sign = -sign;
  }
  return std::clamp(2 * sum, 0.0, 1.0);
}

double ks_p_value(double D, std::size_t n) {
  if (n == 0) return 1;
  const double root = std::sqrt(double(n));
  return kolmogorov_tail((root + 0.12 + 0.11 / root) * D);
}

SpeedHistogram speed_histogram(const std::vector<double>& scaled, int bins, double x_max) {
  SpeedHistogram h;
  h.x_max = x_max;
  h.density.assign(std::size_t(bins), 0.0);
  const double width = x_max / bins;
  for (double x : scaled)
    if (x >= 0 && x < x_max) h.density[std::min(std::size_t(bins - 1), std::size_t(x / width))] += 1;
  for (int b = 0; b < bins; ++b) {
    h.density[std::size_t(b)] /= std::max<double>(1, double(scaled.size())) * width;
    h.maxwell.push_back(maxwell_density((b + 0.5) * width));
  }
  return h;
}

SpeedCheck check_speeds(const System& s, int bins) {
  SpeedCheck c;
  c.T = kinetic_temperature(s);
  c.n = s.particles.size();
  if (c.T <= 0 || c.n == 0) return c;
  const std::vector<double> scaled = scaled_speeds(s, c.T);
  c.histogram = speed_histogram(scaled, bins);
  c.ks_distance = maxwell_ks_distance(scaled);
  c.maxwellian_p = ks_p_value(c.ks_distance, c.n);
  return c;
}

}  // namespace swarm
