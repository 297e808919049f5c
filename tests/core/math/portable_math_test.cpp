#include "math/portable_math.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

// portable_math's functions against the C library's (glibc natively, musl under node), in
// units in the last place, over the arguments the physics uses and well beyond; and a pinned
// hash of their results, which the native and the WebAssembly suites must both reproduce.

namespace pm = swarm::portable;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A small fixed generator (splitmix64), so both builds draw the same arguments.
class Arguments {
 public:
  explicit Arguments(std::uint64_t seed) : state_(seed) {}
  double uniform(double a, double b) { return a + (b - a) * (double(next() >> 11) * 0x1.0p-53); }
  /// |x| in [2^lo, 2^(hi+1)) with a uniformly drawn binary exponent, either sign. Built with
  /// ldexp, which is exact, so that no libm rounding differs between the builds' arguments.
  double log_uniform(int lo, int hi) {
    const int e = lo + int(next() % std::uint64_t(hi - lo + 1));
    const double x = std::ldexp(1.0 + double(next() >> 12) * 0x1.0p-52, e);
    return (next() & 1) ? -x : x;
  }

 private:
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9;
    z = (z ^ (z >> 27)) * 0x94d049bb133111eb;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

/// The doubles in order as unsigned integers: adjacent doubles differ by 1.
std::uint64_t ordered_bits(double x) {
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return (u >> 63) ? ~u : u | (std::uint64_t(1) << 63);
}

/// The distance in ulps between two doubles (0 for two NaNs or two equal values).
double ulps(double a, double b) {
  if (a == b || (std::isnan(a) && std::isnan(b))) return 0;
  const std::uint64_t ua = ordered_bits(a), ub = ordered_bits(b);
  return double(ua > ub ? ua - ub : ub - ua);
}

double worst_ulps(const std::function<double(double)>& ours,
                  const std::function<double(double)>& libm, const std::vector<double>& xs) {
  double worst = 0;
  for (double x : xs) worst = std::max(worst, ulps(ours(x), libm(x)));
  return worst;
}

std::vector<double> draw(int n, const std::function<double(Arguments&)>& one, std::uint64_t seed) {
  Arguments a(seed);
  std::vector<double> xs;
  for (int i = 0; i < n; ++i) xs.push_back(one(a));
  return xs;
}

double sin_of(double x) { return pm::sin(x); }
double cos_of(double x) { return pm::cos(x); }

}  // namespace

TEST_CASE("portable sin and cos are within 1 ulp of libm, out to phases of 1e6 rad and beyond") {
  const auto small = draw(
      20000, [](Arguments& a) { return a.uniform(-10, 10); }, 1);
  const auto phases = draw(
      20000, [](Arguments& a) { return a.uniform(-1e6, 1e6); }, 2);
  // Beyond 2^20 pi/2 the reduction is Payne-Hanek's; up to 1e300.
  const auto huge = draw(
      20000, [](Arguments& a) { return a.log_uniform(20, 1022); }, 3);
  // Next to multiples of pi/2, where x - n pi/2 cancels to a few bits.
  std::vector<double> near_multiples;
  for (double n : {1.0, 2.0, 3.0, 4.0, 5.0, 100.0, 12345.0, 1e6, 1e9}) {
    double x = n * M_PI_2;
    for (int i = 0; i < 20; ++i, x = std::nextafter(x, kInf)) near_multiples.push_back(x);
  }
  const std::vector<double>* sets[] = {&small, &phases, &huge, &near_multiples};
  for (const std::vector<double>* xs : sets) {
    const double s = worst_ulps(
        sin_of, [](double x) { return std::sin(x); }, *xs);
    const double c = worst_ulps(
        cos_of, [](double x) { return std::cos(x); }, *xs);
    MESSAGE("sin ", s, " ulp, cos ", c, " ulp");
    CHECK(s <= 1);
    CHECK(c <= 1);
  }
  for (double x : small) {
    double s, c;
    pm::sincos(x, &s, &c);
    REQUIRE(s == sin_of(x));
    REQUIRE(c == cos_of(x));
  }
  CHECK(sin_of(0.0) == 0.0);
  CHECK(std::signbit(sin_of(-0.0)));
  CHECK(cos_of(0.0) == 1.0);
  CHECK(sin_of(1e-300) == 1e-300);
  CHECK(std::isnan(sin_of(kInf)));
  CHECK(std::isnan(cos_of(-kInf)));
  CHECK(std::isnan(cos_of(kNaN)));
}

// sinh is musl's formula through expm1, which for |x| < 16 can land 2 ulp from glibc's (both
// are within 1.8 ulp of the true value there, measured against long double).
TEST_CASE("portable exp, expm1, cosh (1 ulp) and sinh (2 ulp) agree with libm up to overflow") {
  const auto range = draw(
      20000, [](Arguments& a) { return a.uniform(-745, 709.78); }, 4);
  const auto near_overflow = draw(
      5000, [](Arguments& a) { return a.uniform(700, 709.78); }, 5);
  const auto small = draw(
      20000, [](Arguments& a) { return a.log_uniform(-60, 3); }, 6);
  const auto hyperbolic = draw(
      20000, [](Arguments& a) { return a.uniform(-710, 710); }, 7);
  struct Pair {
    const char* name;
    double (*ours)(double);
    double (*libm)(double);
  };
  const Pair pairs[] = {{"exp", pm::exp, [](double x) { return std::exp(x); }},
                        {"expm1", pm::expm1, [](double x) { return std::expm1(x); }},
                        {"cosh", pm::cosh, [](double x) { return std::cosh(x); }},
                        {"sinh", pm::sinh, [](double x) { return std::sinh(x); }}};
  for (const Pair& p : pairs) {
    for (const std::vector<double>* xs : {&range, &near_overflow, &small, &hyperbolic}) {
      if (p.name[0] == 'e' && xs == &hyperbolic) continue;  // exp overflows past 709.78
      const double worst = worst_ulps(p.ours, p.libm, *xs);
      MESSAGE(std::string(p.name), " ", worst, " ulp");
      CHECK(worst <= (p.ours == pm::sinh ? 2 : 1));
    }
  }
  CHECK(pm::exp(0.0) == 1.0);
  CHECK(pm::exp(710.0) == kInf);
  CHECK(pm::exp(-kInf) == 0.0);
  CHECK(pm::exp(-746.0) == 0.0);
  CHECK(pm::exp(kInf) == kInf);
  CHECK(std::isnan(pm::exp(kNaN)));
  CHECK(pm::expm1(-kInf) == -1.0);
  CHECK(pm::cosh(0.0) == 1.0);
  CHECK(pm::cosh(711.0) == kInf);
  CHECK(pm::sinh(-711.0) == -kInf);
  CHECK(std::signbit(pm::sinh(-0.0)));
  CHECK(pm::cosh(710.4) == doctest::Approx(std::cosh(710.4)).epsilon(1e-15));
}

TEST_CASE("portable log is within 1 ulp of libm over every positive double") {
  const auto all = draw(
      40000, [](Arguments& a) { return std::abs(a.log_uniform(-1074, 1023)); }, 8);
  const auto near_one = draw(
      20000, [](Arguments& a) { return a.uniform(0.5, 2); }, 9);
  // Box-Muller's 1 - u for u in [0, 1) with 53 bits.
  const auto unit = draw(
      20000, [](Arguments& a) { return 1.0 - a.uniform(0, 1); }, 10);
  for (const std::vector<double>* xs : {&all, &near_one, &unit}) {
    const double worst = worst_ulps(
        pm::log, [](double x) { return std::log(x); }, *xs);
    MESSAGE("log ", worst, " ulp");
    CHECK(worst <= 1);
  }
  CHECK(pm::log(1.0) == 0.0);
  CHECK(pm::log(0.0) == -kInf);
  CHECK(pm::log(kInf) == kInf);
  CHECK(std::isnan(pm::log(-1.0)));
  CHECK(pm::log(4.9e-324) == doctest::Approx(std::log(4.9e-324)).epsilon(1e-15));
}

TEST_CASE("portable atan2 is within 1 ulp of libm in every quadrant") {
  Arguments a(11);
  double worst = 0;
  for (int i = 0; i < 40000; ++i) {
    const double y = a.log_uniform(-40, 40), x = a.log_uniform(-40, 40);
    worst = std::max(worst, ulps(pm::atan2(y, x), std::atan2(y, x)));
  }
  MESSAGE("atan2 ", worst, " ulp");
  CHECK(worst <= 1);
  CHECK(pm::atan2(0.0, 1.0) == 0.0);
  CHECK(pm::atan2(0.0, -1.0) == M_PI);
  CHECK(pm::atan2(-0.0, -1.0) == -M_PI);
  CHECK(pm::atan2(1.0, 0.0) == M_PI_2);
  CHECK(pm::atan2(kInf, -kInf) == 3 * M_PI_4);
}

TEST_CASE("portable functions give the pinned bits (native == wasm)") {
  // FNV-1a over the results of every function at fixed arguments; computed by the native
  // build, reproduced by the WebAssembly one only if every result agrees to the bit.
  std::uint64_t hash = 0xcbf29ce484222325;
  const auto add = [&hash](double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    for (int byte = 0; byte < 8; ++byte) {
      hash ^= (bits >> (8 * byte)) & 0xff;
      hash *= 0x100000001b3;
    }
  };
  Arguments a(12);
  for (int i = 0; i < 10000; ++i) {
    const double phase = a.uniform(-1e6, 1e6), huge = a.log_uniform(20, 1022);
    const double e = a.uniform(-745, 709.78), u = 1.0 - a.uniform(0, 1);
    add(pm::sin(phase));
    add(pm::cos(phase));
    add(pm::sin(huge));
    add(pm::cos(huge));
    add(pm::exp(e));
    add(pm::expm1(e / 16));
    add(pm::cosh(e));
    add(pm::sinh(e));
    add(pm::log(u));
    add(pm::log(std::abs(huge)));
    add(pm::atan2(phase, e));
  }
  char text[19];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(hash));
  INFO("hash ", text);
  CHECK(hash == 0x0c4546cddeeaff0cULL);
}
