#include "fast_engine_window.h"

#include <cmath>
#include <limits>

namespace swarm::fast {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

double entry_attractive(const Vec3& a, const Vec3& b, double k, double tau_from, double T2) {
  // With B = b / omega and theta = omega tau:
  // |h|^2 = P + Q cos(2 theta) + S sin(2 theta) = P + A cos(2 theta - phi).
  const double w = std::sqrt(k);
  const Vec3 B = b / w;
  const double aa = a.squaredNorm(), BB = B.squaredNorm();
  const double P = 0.5 * (aa + BB), Q = 0.5 * (aa - BB), S = a.dot(B);
  const double A = std::hypot(Q, S);
  if (T2 <= P - A) return tau_from;  // always at least T away from the origin
  if (T2 > P + A) return kNever;     // never reaches T
  const double alpha = std::acos((T2 - P) / A);
  const double phi = std::atan2(S, Q);
  const double psi = std::remainder(2 * w * tau_from - phi, 2 * M_PI);
  if (std::abs(psi) <= alpha) return tau_from;
  const double ahead = psi > alpha ? 2 * M_PI - alpha - psi : -alpha - psi;
  return tau_from + ahead / (2 * w);
}

double entry_repulsive(const Vec3& a, const Vec3& b, double k, double tau_from, double T2) {
  // h = C e^{Omega tau} + D e^{-Omega tau}; with E = e^{2 Omega tau},
  // E (|h|^2 - T2) = cc E^2 + beta E + dd, beta = 2 C.D - T2.
  const double W = std::sqrt(-k);
  const Vec3 C = 0.5 * (a + b / W), D = 0.5 * (a - b / W);
  const double cc = C.squaredNorm(), dd = D.squaredNorm(), beta = 2 * C.dot(D) - T2;
  const double E = std::exp(2 * W * tau_from);
  if ((cc * E + beta) * E + dd >= 0) return tau_from;
  if (cc <= 0) return kNever;  // only the decaying part: |h| keeps falling
  // Negative somewhere on E > 0, so beta < 0 and the larger root has no cancellation.
  const double disc = std::max(0.0, beta * beta - 4 * cc * dd);
  const double E_plus = (-beta + std::sqrt(disc)) / (2 * cc);
  return std::max(tau_from, std::log(E_plus) / (2 * W));
}

double entry_free(const Vec3& a, const Vec3& b, double tau_from, double T2) {
  const double aa = a.squaredNorm(), ab = a.dot(b), bb = b.squaredNorm();
  if ((bb * tau_from + 2 * ab) * tau_from + aa - T2 >= 0) return tau_from;
  if (bb <= 0) return kNever;
  const double disc = std::max(0.0, ab * ab - bb * (aa - T2));
  return std::max(tau_from, (-ab + std::sqrt(disc)) / bb);
}

}  // namespace

double window_entry(const Vec3& a, const Vec3& b, double k, double tau_from, double T2) {
  if (k > 0) return entry_attractive(a, b, k, tau_from, T2);
  if (k < 0) return entry_repulsive(a, b, k, tau_from, T2);
  return entry_free(a, b, tau_from, T2);
}

}  // namespace swarm::fast
