#include "engine/fast_engine_window_batch.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace swarm;

namespace {

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

/// Orbits of every kind the fast engine meets: a scale from 1e-3 to 1e3 per orbit, with
/// some that never reach T, some always beyond it, some with no growing part.
void random_orbits(std::mt19937_64& rng, std::size_t n, std::vector<Vec3>& a,
                   std::vector<Vec3>& b) {
  std::uniform_real_distribution<double> u(-1, 1), decade(-3, 3);
  a.resize(n);
  b.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double scale = std::pow(10.0, decade(rng));
    a[j] = scale * Vec3(u(rng), u(rng), u(rng));
    b[j] = scale * Vec3(u(rng), u(rng), u(rng));
    if (j % 17 == 3) b[j] = -a[j];  // only the decaying part (C = 0) when omega = 1
    if (j % 23 == 5) a[j] = b[j] = Vec3::Zero();
  }
}

}  // namespace

TEST_CASE("the batched windows are window_of's to the last bit, for every J") {
  std::mt19937_64 rng(20261127);
  for (const double k : {-1.0, -0.37, -2500.0, 1.0, 0.0}) {
    const fast::Spring spring{k, k != 0 ? 1 / std::sqrt(std::abs(k)) : 0.0};
    for (const double T : {1e-3, 0.5, 0.987, 30.0}) {
      for (const double origin : {0.0, 17.25, 4.0e5})
      // Batches that end in a padded group of 3, 2 or 1, or in none.
      for (const std::size_t n : {std::size_t(1003), std::size_t(1002), std::size_t(1),
                                  std::size_t(4)}) {
        std::vector<Vec3> a, b;
        random_orbits(rng, n, a, b);
        std::vector<fast::Window> batch(n);
        fast::windows_of(a.data(), b.data(), n, spring, T * T, origin, batch.data());
        long differing = 0;
        for (std::size_t j = 0; j < n; ++j) {
          const fast::Window one = fast::window_of(a[j], b[j], spring, T * T, origin);
          differing +=
              !same_bits(one.first, batch[j].first) || !same_bits(one.second, batch[j].second);
        }
        INFO("k = " << k << ", T = " << T << ", phase origin = " << origin << ", n = " << n
                    << ", four at once: " << fast::windows_use_avx2());
        CHECK(differing == 0);
      }
    }
  }
}

TEST_CASE("the batched off-centre windows are off_centre_window_of's to the last bit") {
  // Orbits about centres from the container's centre to beyond its wall (the anchors' under
  // gravity are 0.6 to 1.3 R out), of sizes from far inside the threshold to far beyond it,
  // so that every case of the grid of the turn comes up: never, always, arcs that wrap round
  // the turn's start, arcs that close on refinement, windows left to S1.
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> u(-1, 1), decade(-2, 0.5), out(0, 1.4);
  const std::size_t n = 20000;
  for (const double k : {1.0, 0.37, 2500.0, 0.0, -1.0}) {
    const fast::Spring spring{k, k != 0 ? 1 / std::sqrt(std::abs(k)) : 0.0};
    for (const double T : {0.5, 0.987}) {
      for (const double origin : {0.0, 17.25, 4.0e5}) {
        std::vector<Vec3> a(n), b(n);
        const Vec3 w = out(rng) * Vec3(u(rng), u(rng), u(rng)).normalized();
        for (std::size_t j = 0; j < n; ++j) {
          const double scale = std::pow(10.0, decade(rng));
          a[j] = scale * Vec3(u(rng), u(rng), u(rng));
          b[j] = scale * std::sqrt(std::abs(k) + 1e-9) * Vec3(u(rng), u(rng), u(rng));
          if (j % 29 == 7) b[j] = Vec3::Zero();  // through the centre, on a line
          if (j % 31 == 9) a[j] = b[j] = Vec3::Zero();  // at rest at the centre
        }
        std::vector<fast::Window> batch(n);
        fast::off_centre_windows_of(a.data(), b.data(), n, w, spring, T * T, origin,
                                    batch.data());
        long differing = 0, once_a_turn = 0;
        for (std::size_t j = 0; j < n; ++j) {
          const fast::Window one = fast::off_centre_window_of(a[j], b[j], w, spring, T * T, origin);
          differing +=
              !same_bits(one.first, batch[j].first) || !same_bits(one.second, batch[j].second);
          once_a_turn += k > 0 && one.second >= fast::kOnceATurn;
        }
        INFO("k = " << k << ", T = " << T << ", |w| = " << w.norm() << ", phase origin = "
                    << origin << ", four points at once: " << fast::windows_use_avx2());
        CHECK(differing == 0);
        // The grid's arcs were among them (a test of the vector path, not only of S1 and S2).
        if (k > 0 && w.norm() > 0.2) CHECK(once_a_turn > 100);
      }
    }
  }
}
