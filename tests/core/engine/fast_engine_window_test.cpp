#include "engine/fast_engine_window.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "swarm/physics/flow.h"

using namespace swarm;

namespace {

/// A free orbit y(tau) = c(tau) a + s(tau) b about the centre, as the fast engine keeps a
/// particle between two of its wall hits, with a window computed for it at radius T.
struct Orbit {
  Vec3 a, b;
  double k;
};

Vec3 random_vector(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  return scale * Vec3(u(rng), u(rng), u(rng));
}

struct Search {
  long outward_crossings = 0;  // the brute force's wall hits: |y| passes T going out
  long outside_samples = 0;    // samples with |y| >= T
  long missed = 0;             // of those, outside the window
  long wrongly_inside = 0;     // samples clearly inside the sphere but in the window
};

/// Walks the exact closed-form orbit in fine sub-steps h from t0 to t0 + duration and asks
/// the window, through span_of as the scheduler does, whether each sample lies inside it.
void search(const Orbit& o, double T, double t0, double duration, double h, Search& out) {
  const double phase_per_time = o.k != 0 ? 2 * std::sqrt(std::abs(o.k)) : 1.0;
  const fast::Spring spring{o.k, o.k != 0 ? 1 / std::sqrt(std::abs(o.k)) : 0.0};
  const fast::Window w = fast::window_of(o.a, o.b, spring, T * T, phase_per_time * t0);
  double last_r2 = o.a.squaredNorm();
  const long samples = long(duration / h);
  for (long j = 0; j <= samples; ++j) {
    const double tau = double(j) * h;
    const Flow f = Flow::over(o.k, tau);
    const double r2 = (f.c * o.a + f.s * o.b).squaredNorm();
    // span_of with a clock at the sample: the window has begun there iff begin == 0.
    const fast::Clock clock{o.k, phase_per_time, 1.0, t0 + tau};
    const bool in_window = fast::span_of(w, clock).begin == 0;
    if (r2 >= T * T) {
      ++out.outside_samples;
      if (!in_window) ++out.missed;
      if (j > 0 && last_r2 < T * T) ++out.outward_crossings;
    } else if (in_window && r2 < T * T * (1 - 1e-6)) {
      ++out.wrongly_inside;
    }
    last_r2 = r2;
  }
}

/// Many random orbits of stiffness k: every sample the brute force finds at or beyond the
/// wall lies inside the orbit's window, and the window is no wider than the rounding.
Search search_many(double k, double duration, double h, double speed) {
  std::mt19937_64 rng(k > 0 ? 11 : k < 0 ? 12 : 13);
  Search out;
  for (int n = 0; n < 40; ++n) {
    const Orbit o{random_vector(rng, 0.8), random_vector(rng, speed), k};
    // Epochs that began at various times: the windows count their phase from 0.
    const double t0 = n % 4 == 0 ? 0.0 : 37.25 * n;
    search(o, 0.9, t0, duration, h, out);
  }
  return out;
}

}  // namespace

TEST_CASE("every wall crossing of a free orbit lies in its window (J > 0)") {
  // Ellipses about the centre: several turns each, some of which reach beyond T.
  const Search s = search_many(+1.0, 20.0, 2e-4, 1.2);
  CHECK(s.outward_crossings > 40);
  CHECK(s.outside_samples > 1000);
  CHECK(s.missed == 0);
  CHECK(s.wrongly_inside == 0);
}

TEST_CASE("every wall crossing of a free orbit lies in its window (J < 0)") {
  // Runaway hyperbolas, some on their way in before they turn (a window in two parts).
  const Search s = search_many(-1.0, 3.0, 5e-5, 1.5);
  CHECK(s.outward_crossings > 20);
  CHECK(s.outside_samples > 1000);
  CHECK(s.missed == 0);
  CHECK(s.wrongly_inside == 0);
}

TEST_CASE("every wall crossing of a free orbit lies in its window (J = 0)") {
  // Straight lines: in, through and out of the sphere once.
  const Search s = search_many(0.0, 4.0, 5e-5, 1.0);
  CHECK(s.outward_crossings > 20);
  CHECK(s.outside_samples > 1000);
  CHECK(s.missed == 0);
  CHECK(s.wrongly_inside == 0);
}

TEST_CASE("an orbit that never reaches the wall has no window, one that never leaves it has") {
  const fast::Spring spring{1.0, 1.0};
  // |y| = 0.5 on a circle: never at T = 0.9, always at T = 0.4.
  const Vec3 a(0.5, 0, 0), b(0, 0.5, 0);
  const fast::Clock clock{1.0, 2.0, 1.0, 3.0};
  CHECK(fast::span_of(fast::window_of(a, b, spring, 0.81, 0.0), clock).begin ==
        std::numeric_limits<double>::infinity());
  const fast::Span always = fast::span_of(fast::window_of(a, b, spring, 0.16, 0.0), clock);
  CHECK(always.begin == 0);
  CHECK(always.end == std::numeric_limits<double>::infinity());
}
