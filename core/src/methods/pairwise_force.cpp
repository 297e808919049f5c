#include <cmath>
#include <vector>
#ifndef __EMSCRIPTEN__
#include <thread>
#endif

#include "swarm/methods/integrators.h"

// The accumulators never alias the positions: telling the compiler lets it vectorise the
// partner loop without run-time overlap checks (g++ and clang, hence also emcc, know it).
#if defined(__GNUC__)
#define SWARM_RESTRICT __restrict__
#else
#define SWARM_RESTRICT
#endif

namespace swarm {
namespace {

// Below this many particles a second thread costs more than it saves.
[[maybe_unused]] constexpr std::size_t kThreadedPairs = 400;  // threads only exist natively

struct Columns {
  std::vector<double> x, y, z, m;
};

/// Adds the pair forces of rows [begin, end) (each pair i < k once) to ax, ay, az. Each pair
/// is summed honestly: the force on k is minus the force on i (Newton's third law).
void add_rows(const Columns& c, std::size_t begin, std::size_t end, double* SWARM_RESTRICT ax,
              double* SWARM_RESTRICT ay, double* SWARM_RESTRICT az) {
  const std::size_t n = c.x.size();
  const double* SWARM_RESTRICT x = c.x.data();
  const double* SWARM_RESTRICT y = c.y.data();
  const double* SWARM_RESTRICT z = c.z.data();
  const double* SWARM_RESTRICT m = c.m.data();
  for (std::size_t i = begin; i < end; ++i) {
    const double xi = x[i], yi = y[i], zi = z[i], mi = m[i];
    double sx = 0, sy = 0, sz = 0;
    // Structure of arrays: the loop over partners vectorises.
    for (std::size_t k = i + 1; k < n; ++k) {
      const double dx = xi - x[k], dy = yi - y[k], dz = zi - z[k];
      sx += m[k] * dx;
      sy += m[k] * dy;
      sz += m[k] * dz;
      ax[k] += mi * dx;
      ay[k] += mi * dy;
      az[k] += mi * dz;
    }
    ax[i] -= sx;
    ay[i] -= sy;
    az[i] -= sz;
  }
}

}  // namespace

void pairwise_accelerations(const System& s, std::vector<Vec3>& a, int threads) {
  const std::size_t n = s.particles.size();
  Columns c;
  c.x.resize(n);
  c.y.resize(n);
  c.z.resize(n);
  c.m.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.x[i] = s.particles[i].r.x();
    c.y[i] = s.particles[i].r.y();
    c.z[i] = s.particles[i].r.z();
    c.m[i] = s.particles[i].m;
  }
  // Two blocks of rows with about as many pairs each (row i has n - 1 - i), each summed into
  // its own arrays and then added in a fixed order: the result is the same whether the blocks
  // run on two threads or, as in the browser, one after the other.
  const auto split = std::size_t(double(n) * (1 - std::sqrt(0.5)));
  std::vector<double> first(3 * n, 0.0), second(3 * n, 0.0);
  auto block = [&](std::vector<double>& acc, std::size_t begin, std::size_t end) {
    add_rows(c, begin, end, acc.data(), acc.data() + n, acc.data() + 2 * n);
  };
#ifdef __EMSCRIPTEN__
  (void)threads;  // the browser build has no threads
#else
  if (n >= kThreadedPairs && threads >= 2) {
    std::thread helper([&] { block(second, split, n); });
    block(first, 0, split);
    helper.join();
  } else
#endif
  {
    block(first, 0, split);
    block(second, split, n);
  }
  a.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    a[i] = s.J * Vec3(first[i] + second[i], first[n + i] + second[n + i],
                      first[2 * n + i] + second[2 * n + i]);
}

}  // namespace swarm
