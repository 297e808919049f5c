#include <algorithm>
#include <cmath>
#include <vector>
#ifndef __EMSCRIPTEN__
#include <atomic>
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
// The rows are cut into blocks of about this many pairs (at least 2 blocks, at most
// kMaxBlocks), whatever the thread count: each block has its own accumulators, a pass of 3 N
// additions at the end, small beside its pairs.
constexpr std::size_t kPairsPerBlock = 50000;
constexpr std::size_t kMaxBlocks = 64;

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
  // Blocks of rows with about as many pairs each (row i has n - 1 - i; the rows before block
  // b's first hold b / blocks of the pairs), each summed into its own arrays and then added in
  // block order: the block count depends on n alone, so the result is the same on any number
  // of threads or, as in the browser, one block after the other.
  const std::size_t blocks =
      std::clamp<std::size_t>(n * (n > 0 ? n - 1 : 0) / 2 / kPairsPerBlock, 2, kMaxBlocks);
  std::vector<std::size_t> first_row(blocks + 1, n);
  for (std::size_t b = 0; b < blocks; ++b)
    first_row[b] = std::size_t(double(n) * (1 - std::sqrt(1 - double(b) / double(blocks))));
  std::vector<std::vector<double>> acc(blocks, std::vector<double>(3 * n, 0.0));
  auto block = [&](std::size_t b) {
    add_rows(c, first_row[b], first_row[b + 1], acc[b].data(), acc[b].data() + n,
             acc[b].data() + 2 * n);
  };
#ifdef __EMSCRIPTEN__
  (void)threads;  // the browser build has no threads
#else
  const auto helpers = std::size_t(std::clamp(threads, 1, int(blocks))) - 1;
  if (n >= kThreadedPairs && helpers > 0) {
    // Whichever thread is free takes the next block.
    std::atomic<std::size_t> next{0};
    auto take_blocks = [&] {
      for (std::size_t b; (b = next.fetch_add(1)) < blocks;) block(b);
    };
    std::vector<std::thread> pool;
    for (std::size_t h = 0; h < helpers; ++h) pool.emplace_back(take_blocks);
    take_blocks();
    for (std::thread& t : pool) t.join();
  } else
#endif
  {
    for (std::size_t b = 0; b < blocks; ++b) block(b);
  }
  a.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 sum(acc[0][i], acc[0][n + i], acc[0][2 * n + i]);
    for (std::size_t b = 1; b < blocks; ++b)
      sum += Vec3(acc[b][i], acc[b][n + i], acc[b][2 * n + i]);
    a[i] = s.J * sum;
  }
}

}  // namespace swarm
