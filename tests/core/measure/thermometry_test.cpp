#include "swarm/measure/thermometry.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "swarm/measure/blocking.h"
#include "swarm/preset/preset.h"
#include "swarm/run/run.h"

using namespace swarm;
using doctest::Approx;

TEST_CASE("wall pressure and temperature follow the paper's definitions, by hand") {
  // One particle of mass 2 hits the wall head-on at speed 3 with tangential speed 4.
  Particle p{2.0, {0, 0, 1}, {4, 0, 3}};
  WallTally t;
  reflect_at_wall(p, t);
  CHECK(t.hits == 1);
  CHECK(t.radial_impulse == Approx(2 * 2.0 * 3));
  CHECK(t.hit_kinetic_energy == Approx(0.5 * 2.0 * 25));
  CHECK((p.v - Vec3(4, 0, -3)).norm() < 1e-15);
  CHECK((t.wall_momentum - Vec3(0, 0, 12)).norm() < 1e-15);

  WallMeter meter;
  const double R = 2.0, dt = 0.01;
  meter.add(t, dt, sphere_area(R));
  meter.add(WallTally{}, dt, sphere_area(R));
  const WallReading w = meter.reading();
  CHECK(w.P == Approx(12.0 / (4 * M_PI * R * R * 2 * dt)));
  CHECK(w.T == Approx(0.5 * 25.0));  // half the hitters' mean kinetic energy (k_B = 1)
  meter.reset();
  CHECK(meter.reading().P == 0);
  CHECK(meter.reading().T == 0);
}

namespace {

/// Four intervals by hand; the second and the fourth had no wall hit.
std::vector<WallInterval> intervals_with_gaps() {
  return {{1.0, 1.0, {2.0, 3.0, 4}},
          {2.0, 1.0, {1.0, 0.0, 0}},
          {2.5, 0.5, {4.0, 6.0, 2}},
          {3.5, 1.0, {0.0, 0.0, 0}}};
}

void check_reading(const WallReading& w, double P, double T, std::int64_t hits) {
  CHECK(w.P == Approx(P));
  CHECK(w.T == Approx(T));
  CHECK(w.hits == hits);
}

}  // namespace

TEST_CASE("the wall average weighs P by time and T by hits; hitless intervals add nothing to T") {
  const std::vector<WallInterval> in = intervals_with_gaps();
  // P: impulse per area 2*1 + 1*1 + 4*0.5 + 0 = 5 over 3.5 time units. T: 4 hits at 3 and 2
  // at 6 give (12 + 12) / 6 = 4; the unweighted mean over intervals with hits would be 4.5 and
  // counting the hitless ones as T = 0 would give 2.25.
  check_reading(wall_average(in, 0, 4), 5.0 / 3.5, 4.0, 6);
  check_reading(wall_average(in, 1, 2), 1.0, 0.0, 0);  // nothing hit: T = 0 by convention
  check_reading(wall_average(in, 1, 3), 3.0 / 1.5, 6.0, 2);
}

TEST_CASE("windowed wall averages: trailing, centred and zero windows, by hand") {
  const std::vector<WallInterval> in = intervals_with_gaps();
  // Trailing 1.5: the intervals ending in (t - 1.5, t].
  const std::vector<WallReading> trailing = windowed_wall_averages(in, 1.5, 0);
  REQUIRE(trailing.size() == 4);
  check_reading(trailing[0], 2.0, 3.0, 4);        // {0}
  check_reading(trailing[1], 3.0 / 2.0, 3.0, 4);  // {0, 1}: the hitless one leaves T at 3
  check_reading(trailing[2], 3.0 / 1.5, 6.0, 2);  // {1, 2}
  check_reading(trailing[3], 2.0 / 1.5, 6.0, 2);  // {2, 3}: interval 1 ends at 2, outside
  // Centred, 1 either side: the intervals ending in (t - 1, t + 1].
  const std::vector<WallReading> centred = windowed_wall_averages(in, 1, 1);
  check_reading(centred[0], 3.0 / 2.0, 3.0, 4);  // {0, 1}
  check_reading(centred[1], 3.0 / 1.5, 6.0, 2);  // {1, 2}
  check_reading(centred[2], 3.0 / 2.5, 6.0, 2);  // {1, 2, 3}
  check_reading(centred[3], 0.0, 0.0, 0);        // {3}: no hit in the window, so T = 0
  // No window: every interval's own reading.
  const std::vector<WallReading> own = windowed_wall_averages(in, 0, 0);
  for (std::size_t i = 0; i < in.size(); ++i)
    check_reading(own[i], in[i].reading.P, in[i].reading.T, in[i].reading.hits);
}

TEST_CASE("the wall average of intervals equals one meter over all of their steps") {
  // Steps with and without hits, split into three intervals; the container grows in between,
  // as in an expansion, so the per-step area matters.
  const WallTally hit{3, 6.0, 9.0, Vec3::Zero()}, none{};
  const WallTally steps[] = {hit, none, none, hit, none, hit, hit, none, none};
  const double dt = 0.1, radius[] = {1.0, 1.5, 2.0};
  WallMeter whole, part;
  std::vector<WallInterval> intervals;
  for (int i = 0; i < 9; ++i) {
    whole.add(steps[i], dt, radius[i / 3]);
    part.add(steps[i], dt, radius[i / 3]);
    if (i % 3 == 2) {
      intervals.push_back({dt * (i + 1), 3 * dt, part.reading()});  // three steps each
      part.reset();
    }
  }
  const WallReading expected = whole.reading();
  check_reading(wall_average(intervals, 0, intervals.size()), expected.P, expected.T,
                expected.hits);
}

namespace {

/// Unit intervals ending at 1, 2, ...; the wall at radius 1 unless given.
std::vector<WallInterval> unit_intervals(const std::vector<double>& P,
                                         const std::vector<double>& T,
                                         const std::vector<std::int64_t>& hits,
                                         const std::vector<double>& R = {}) {
  std::vector<WallInterval> out;
  for (std::size_t i = 0; i < P.size(); ++i)
    out.push_back({double(i + 1), 1.0, {P[i], T[i], hits[i]}, R.empty() ? 1.0 : R[i]});
  return out;
}

/// The standard deviation (over n) of the values, times sqrt(history / (history - window)).
double overlapping_error(const std::vector<double>& v, double history, double window) {
  double mean = 0, squares = 0;
  for (double x : v) mean += x / double(v.size());
  for (double x : v) squares += (x - mean) * (x - mean);
  return std::sqrt(squares / double(v.size()) * history / (history - window));
}

}  // namespace

TEST_CASE("wall_estimate: the error is the spread of earlier windows of the same length") {
  // Nine unit intervals; the window of 2 holds the last two. Its history is all nine (at most
  // 16 windows back), and the windows of 2 ending at intervals 2..9 are its eight values.
  const std::vector<double> P = {1, 3, 2, 4, 2, 2, 5, 1, 3};
  const std::vector<double> T = {1, 0, 2, 1, 3, 1, 1, 2, 1};
  const std::vector<std::int64_t> hits = {1, 0, 1, 2, 1, 1, 3, 1, 2};
  const WallEstimate e = wall_estimate(unit_intervals(P, T, hits), 2.0);
  CHECK(e.source == WallErrorSource::history);
  CHECK(e.intervals == 2);
  CHECK(e.window == Approx(2.0));
  CHECK(e.history == Approx(9.0));
  CHECK(e.mean.P == Approx(2.0));
  CHECK(e.mean.T == Approx((2.0 * 1 + 1.0 * 2) / 3));
  std::vector<double> window_P, window_T;
  for (int j = 1; j < 9; ++j) {
    window_P.push_back((P[j - 1] + P[j]) / 2);
    window_T.push_back((T[j - 1] * hits[j - 1] + T[j] * hits[j]) / double(hits[j - 1] + hits[j]));
  }
  REQUIRE(e.P_stderr);
  REQUIRE(e.T_stderr);
  CHECK(*e.P_stderr == Approx(overlapping_error(window_P, 9, 2)));
  CHECK(*e.T_stderr == Approx(overlapping_error(window_T, 9, 2)));
}

TEST_CASE("wall_estimate: a wall that moved starts the history afresh; short ones get no ±") {
  // The wall grew after interval 4: the window of 2 has the five intervals since as history,
  // less than four windows, and too few intervals for its own parts: no ±; a window of 1 has
  // 5 >= 4 windows of history.
  const std::vector<double> P = {9, 9, 9, 9, 1, 3, 2, 4, 2};
  const std::vector<double> T = {1, 1, 1, 1, 1, 2, 1, 3, 1};
  const std::vector<std::int64_t> hits = {1, 1, 1, 1, 1, 1, 1, 1, 1};
  const std::vector<double> R = {1, 1, 1, 1, 2, 2, 2, 2, 2};
  const auto in = unit_intervals(P, T, hits, R);
  const WallEstimate two = wall_estimate(in, 2.0);
  CHECK(two.source == WallErrorSource::none);
  CHECK_FALSE(two.P_stderr);
  const WallEstimate one = wall_estimate(in, 1.0);
  CHECK(one.source == WallErrorSource::history);
  CHECK(one.history == Approx(5.0));
  CHECK(*one.P_stderr == Approx(overlapping_error({1, 3, 2, 4, 2}, 5, 1)));

  // The whole run as the window (0), nine intervals: fewer than its parts need, so no ±
  // (blocking gave one here, too large for regular motion).
  const WallEstimate all = wall_estimate(in, 0);
  CHECK(all.source == WallErrorSource::none);
  CHECK(all.intervals == 9);
  CHECK_FALSE(all.P_stderr);
  CHECK_FALSE(all.T_stderr);

  CHECK(wall_estimate({}, 1.0).intervals == 0);
}

TEST_CASE("wall_estimate from the window's parts: a quarter's error carried on to the whole") {
  // 64 unit intervals (the fewest the parts need): P repeats 1, 3 (an impulse every other
  // interval, like a particle at steady intervals): every window of even length has mean 2
  // exactly, so the error is 0 (blocking gave 0.25 per interval's spread). A sixty-third
  // interval fewer: no ±.
  std::vector<double> P, T;
  std::vector<std::int64_t> hits;
  for (int i = 0; i < 64; ++i) P.push_back(i % 2 ? 3 : 1), T.push_back(1), hits.push_back(1);
  const WallEstimate e = wall_estimate(unit_intervals(P, T, hits), 0);
  CHECK(e.source == WallErrorSource::parts);
  REQUIRE(e.P_stderr);
  CHECK(*e.P_stderr == Approx(0).epsilon(1e-12));
  P.pop_back(), T.pop_back(), hits.pop_back();
  CHECK(wall_estimate(unit_intervals(P, T, hits), 0).source == WallErrorSource::none);
}

namespace {

/// A gas for the honesty check below: 100 particles of unit mass in equilibrium in a ball of
/// radius 1 (uniform, Maxwellian at T = 1, CM at rest), with the given J and wall, sampled
/// every 0.01 for 30 time units.
Run gas_run(double J, bool hot_wall, unsigned seed) {
  const std::string preset =
      std::string("{\"version\": 1, \"name\": \"gas\", \"J\": ") + std::to_string(J) +
      ", \"particles\": {\"count\": 100, \"position_radius\": 0.999, \"velocity\": "
      "{\"temperature\": 1}, \"cm_at_rest\": true, \"seed\": " + std::to_string(seed) +
      "}, \"container\": {\"radius\": 1" + (hot_wall ? ", \"wall_temperature\": 1" : "") +
      "}, \"dt\": 0.001, \"duration\": 30, \"sample_every\": 10}";
  const PresetParse p = parse_preset(preset);
  REQUIRE(p.preset);
  Run run(initial_system(*p.preset), run_plan(*p.preset));
  run.finish();
  return run;
}

/// For one run: the estimates at the ends of its disjoint windows after t = 12 (four long
/// windows of history), each from the samples up to that end.
std::vector<WallEstimate> window_estimates(const std::vector<WallInterval>& intervals,
                                           double window) {
  std::vector<WallEstimate> out;
  std::size_t last = 0;
  for (double end = 12 + window; end <= 30 + 1e-9; end += window) {
    while (last < intervals.size() && intervals[last].t_end <= end + 1e-9) ++last;
    out.push_back(wall_estimate({intervals.begin(), intervals.begin() + long(last)}, window));
  }
  return out;
}

/// sqrt(mean of squares), of differences with `degrees` degrees of freedom in `squares`.
struct Spread {
  double squares = 0, quoted = 0;
  long degrees = 0, readings = 0;
  double ratio() const {
    return std::sqrt(squares / double(degrees)) / std::sqrt(quoted / double(readings));
  }
};

}  // namespace

TEST_CASE("wall_estimate's ± is honest: it matches the spread of window means, short and long") {
  // What the ± claims: how far one window's mean falls from the value it estimates. Measured
  // directly over 24 seeds, at every disjoint window after t = 12, against the rms of the ±
  // quoted at each window's end from the samples up to it:
  // - P of an ideal gas (J = 0) against the virial theorem's exact 2 KE / (3 V) for its seed
  //   (KE does not change at a fixed wall, and differs between seeds);
  // - P at a hot wall against N T_wall / V, the same for every seed (the gas starts in
  //   equilibrium at the wall's temperature): the spread between seeds;
  // - otherwise (J > 0, and every T) about each seed's own mean of its windows.
  // The spread has at least 120 degrees of freedom (its sd within 13 % at 95 %), and the
  // quoted side varies too: the ratio must be in 0.8 - 1.25, at windows shorter and longer
  // than a crossing time (about 1.3). Three disjoint sets of 24 seeds gave 0.87 - 1.09.
  struct Gas {
    const char* name;
    double J;
    bool hot_wall;
  };
  const double V = 4 * M_PI / 3;
  for (const Gas gas : {Gas{"J = 0", 0.0, false}, Gas{"J > 0, omega = 2", 4.0 / 100, false},
                        Gas{"hot wall", 0.0, true}}) {
    std::vector<std::vector<WallInterval>> runs;
    std::vector<double> kinetic;
    for (unsigned seed = 1; seed <= 24; ++seed) {
      Run run = gas_run(gas.J, gas.hot_wall, seed);
      runs.push_back(wall_intervals(run.samples()));
      kinetic.push_back(run.samples().front().KE);
    }
    for (const double window : {0.3, 3.0}) {
      Spread P, T;
      for (std::size_t k = 0; k < runs.size(); ++k) {
        const std::vector<WallEstimate> e = window_estimates(runs[k], window);
        double mean_P = 0, mean_T = 0;
        for (const WallEstimate& w : e) {
          REQUIRE(w.source == WallErrorSource::history);
          mean_P += w.mean.P / double(e.size());
          mean_T += w.mean.T / double(e.size());
          P.quoted += *w.P_stderr * *w.P_stderr;
          T.quoted += *w.T_stderr * *w.T_stderr;
        }
        double reference_P = mean_P;
        P.degrees += long(e.size()) - 1;
        if (gas.J == 0 && !gas.hot_wall) reference_P = 2 * kinetic[k] / (3 * V), ++P.degrees;
        if (gas.hot_wall) reference_P = 100 * 1.0 / V, ++P.degrees;
        for (const WallEstimate& w : e) {
          P.squares += (w.mean.P - reference_P) * (w.mean.P - reference_P);
          T.squares += (w.mean.T - mean_T) * (w.mean.T - mean_T);
        }
        P.readings += long(e.size());
        T.readings += long(e.size());
        T.degrees += long(e.size()) - 1;
      }
      MESSAGE(std::string(gas.name) << ", window " << window << ": spread / quoted: P " << P.ratio()
                       << ", T " << T.ratio());
      CHECK(P.ratio() > 0.8);
      CHECK(P.ratio() < 1.25);
      CHECK(T.ratio() > 0.8);
      CHECK(T.ratio() < 1.25);
    }
  }
}

namespace {

/// A run of `count` particles started Maxwellian at T = 1 in a ball of radius 1, sampled
/// every `sample` of time; `extra` adds preset keys.
Run small_gas(double J, int count, double position_radius, double dt, double duration,
              int sample_every, const std::string& extra, unsigned seed) {
  const std::string preset =
      "{\"version\": 1, \"name\": \"gas\", \"J\": " + std::to_string(J) +
      ", \"particles\": {\"count\": " + std::to_string(count) + ", \"position_radius\": " +
      std::to_string(position_radius) +
      ", \"velocity\": {\"temperature\": 1}, \"cm_at_rest\": true, \"seed\": " +
      std::to_string(seed) + "}, \"container\": {\"radius\": 1}" + extra +
      ", \"dt\": " + std::to_string(dt) + ", \"duration\": " + std::to_string(duration) +
      ", \"sample_every\": " + std::to_string(sample_every) + "}";
  const PresetParse p = parse_preset(preset);
  REQUIRE(p.preset);
  Run run(initial_system(*p.preset), run_plan(*p.preset));
  run.finish();
  return run;
}

/// The intervals that end in (from, to].
std::vector<WallInterval> between(const std::vector<WallInterval>& in, double from, double to) {
  std::vector<WallInterval> out;
  for (const WallInterval& i : in)
    if (i.t_end > from + 1e-9 && i.t_end <= to + 1e-9) out.push_back(i);
  return out;
}

/// How often value ± 1.96 se covered the reference, and the rms of (value - reference) over
/// the rms of se (1 when the ± is the right size).
struct Coverage {
  long runs = 0, covered = 0;
  double squares = 0, quoted = 0;
  void add(double difference, double se) {
    ++runs;
    covered += std::abs(difference) <= 1.96 * se;
    squares += difference * difference;
    quoted += se * se;
  }
  double fraction() const { return double(covered) / double(runs); }
  double ratio() const { return std::sqrt(squares / quoted); }
};

}  // namespace

TEST_CASE("the ± of a whole window (an ensemble run's) covers that run's long-run P 95 % of the time") {
  // The window is the run's stretch after t = 1, with no history before it (as an ensemble
  // run's averaging window, or the read-outs' whole run), so its ± comes from its own parts.
  // J = 0 (regular motion: each particle hits the wall at steady intervals), 60 seeds of 100
  // particles over [1, 6]: against the virial theorem's exact long-run 2 KE / (3 V) of each
  // seed. Blocking quoted 3.5x the true error here (ratio 0.3, coverage 100 %).
  // J = 0.01 (omega = 1), 40 seeds of 100 over [1, 6]: against the same seed's mean over
  // [6, 20] (its long-run value, within its own ± from its parts, added in quadrature).
  // Coverage near 95 %: with 60 (40) runs its standard deviation is 2.8 % (3.4 %), so the
  // band is 0.85 - 1; the ratio of the rms error to the rms ± is 0.7 - 1.3 (the ± too large
  // by more than 1.4x, or too small by 1.3x, fails). Measured: 0.95 and 0.91 (J = 0), 0.95 and
  // 0.87 (J = 0.01; J = -0.005: 0.95 and 0.94). What varies more slowly than a quarter of the
  // window is not seen: J = 0.08 with hard spheres, whose P wanders over tens of time units,
  // covered 0.73 of its later mean.
  const double V = 4 * M_PI / 3;
  Coverage ideal, attracting;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    Run run = small_gas(0, 100, 0.999, 0.001, 6, 10, "", seed);
    const WallEstimate e = wall_estimate(between(wall_intervals(run.samples()), 1, 6), 0);
    REQUIRE(e.source == WallErrorSource::parts);
    ideal.add(e.mean.P - 2 * run.samples().front().KE / (3 * V), *e.P_stderr);
  }
  for (unsigned seed = 1; seed <= 40; ++seed) {
    Run run = small_gas(0.01, 100, 0.999, 0.001, 20, 10, "", seed);
    const std::vector<WallInterval> in = wall_intervals(run.samples());
    const WallEstimate e = wall_estimate(between(in, 1, 6), 0);
    const WallEstimate later = wall_estimate(between(in, 6, 20), 0);
    REQUIRE(e.source == WallErrorSource::parts);
    REQUIRE(later.source == WallErrorSource::parts);
    attracting.add(e.mean.P - later.mean.P, std::hypot(*e.P_stderr, *later.P_stderr));
  }
  MESSAGE("J = 0: covered " << ideal.fraction() << ", error / ± " << ideal.ratio()
                            << "; J = 0.01: covered " << attracting.fraction() << ", error / ± "
                            << attracting.ratio());
  for (const Coverage* c : {&ideal, &attracting}) {
    CHECK(c->fraction() >= 0.85);
    CHECK(c->ratio() > 0.7);
    CHECK(c->ratio() < 1.3);
  }
}
