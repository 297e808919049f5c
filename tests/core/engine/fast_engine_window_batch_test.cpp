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
