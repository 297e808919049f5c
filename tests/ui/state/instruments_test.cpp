#include "ui/state/instruments.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "swarm/preset/preset.h"

namespace swarmlab {
namespace {

swarm::Preset shipped(const std::string& name) {
  std::ifstream in(std::string(SWARM_PRESET_DIR) + "/" + name);
  std::stringstream text;
  text << in.rdbuf();
  swarm::PresetParse parsed = swarm::parse_preset(text.str());
  REQUIRE_MESSAGE(parsed.preset, parsed.error);
  return *parsed.preset;
}

}  // namespace

TEST_CASE("instruments: the selected particle's meter times its returns at 2 pi / sqrt(J M)") {
  // Two unit masses 1 apart on a circle, J = 1: M = 2, omega = sqrt(2).
  LiveRun run(shipped("two-body-circular.json"));
  Instruments in;
  const double period = 2 * M_PI / std::sqrt(1.0 * 2.0);
  in.update(run, 0, 0, false);
  REQUIRE(in.track);
  // x about the centre of mass at the start: particle 0 sits at -0.5, the CM at 0.
  CHECK(in.track->x_start == doctest::Approx(-0.5).epsilon(1e-15));
  while (run.time() < 1.8 * period) {
    run.advance(1);
    in.update(run, 0, 0, false);
  }
  REQUIRE(in.track->meter.period());
  CHECK(*in.track->meter.period() == doctest::Approx(period).epsilon(1e-6));
  // One record a frame, each x(t) = -0.5 cos(omega t) on the circle.
  REQUIRE(in.track->t.size() == in.track->x.size());
  const double t = in.track->t.back();
  CHECK(in.track->x.back() == doctest::Approx(-0.5 * std::cos(std::sqrt(2.0) * t)).epsilon(1e-9));
  // The stopwatch reads the simulated clock.
  in.stopwatch.start(run.time());
  run.advance(25);
  in.update(run, 0, 0, false);
  CHECK(in.stopwatch.elapsed() == doctest::Approx(25 * run.preset().dt).epsilon(1e-12));
}

TEST_CASE("instruments: a new selection or no selection starts the timing afresh") {
  LiveRun run(shipped("two-body-circular.json"));
  Instruments in;
  in.update(run, 0, 0, false);
  run.advance(10);
  in.update(run, 0, 0, false);
  REQUIRE(in.track->t.size() == 2);
  in.update(run, 1, 0, false);
  REQUIRE(in.track);
  CHECK(in.track->particle == 1);
  CHECK(in.track->t.size() == 1);
  CHECK(in.track->x_start == doctest::Approx(0.5 * std::cos(std::sqrt(2.0) * run.time())));
  in.update(run, std::nullopt, 0, false);
  CHECK_FALSE(in.track);
  in.update(run, 7, 0, false);  // no such particle
  CHECK_FALSE(in.track);
}

TEST_CASE("instruments: P and T at the wall only in a container, over the averaging window") {
  LiveRun run(shipped("fig4-equilibration.json"));
  Instruments in;
  run.advance(2000);
  in.update(run, std::nullopt, 0, false);
  CHECK(in.wall.intervals == 0);
  const double window = 0.5 * run.time();
  in.update(run, std::nullopt, window, true);
  CHECK(in.wall.intervals > 0);
  // The instruments only feed the core's estimate: the same numbers as asking it directly.
  const swarm::WallEstimate direct =
      swarm::wall_estimate(swarm::wall_intervals(run.primary().samples()), window);
  CHECK(in.wall.mean.hits == direct.mean.hits);
  CHECK(in.wall.mean.P == direct.mean.P);
  CHECK(in.wall.mean.T == direct.mean.T);
  CHECK(in.wall.window == direct.window);
  CHECK(direct.mean.hits > 0);
}

TEST_CASE("instruments: a gas released from a small ball is out of virial balance, by 2 KE") {
  // J = 0, 400 particles within half the container's radius: until they reach the wall they
  // fly free, so G = sum m r.v grows as 2 KE t while P stays 0, and over a window before the
  // first hits mean(3PV) - mean(2KE - 2U) = -2 KE. The read-outs warn from this.
  const swarm::PresetParse parsed = swarm::parse_preset(
      R"({"J": 0, "particles": {"count": 400, "position_radius": 0.5,
          "velocity": {"temperature": 0.2}, "seed": 3},
          "container": {"radius": 1}, "dt": 0.001, "duration": 2})");
  REQUIRE_MESSAGE(parsed.preset, parsed.error);
  LiveRun run(*parsed.preset);
  Instruments in;
  run.advance(300);  // t = 0.3: a particle needs a speed over 1.67 (3.7 sigma) to hit by then
  in.update(run, std::nullopt, 0.2, true);
  REQUIRE(in.virial);
  CHECK_FALSE(in.virial->holds);
  double KE = 0;
  for (const swarm::Particle& q : run.system().particles) KE += 0.5 * q.m * q.v.squaredNorm();
  CHECK(in.virial->imbalance == doctest::Approx(-2 * KE).epsilon(0.05));
  // Nothing is recomputed while no sample arrives (a paused run).
  const double imbalance = in.virial->imbalance;
  in.update(run, std::nullopt, 0.2, true);
  CHECK(in.virial->imbalance == imbalance);
}

TEST_CASE("instruments: the short history's ± is shown only while it is smaller than the value") {
  using swarm::WallErrorSource;
  // The reported case: P = 84.26 with a ± of 170 from the window's parts is shown bare.
  CHECK_FALSE(shown_wall_error(84.26, 170.0, WallErrorSource::parts));
  CHECK_FALSE(shown_wall_error(84.26, 84.26, WallErrorSource::parts));
  CHECK_FALSE(shown_wall_error(-2.0, 3.0, WallErrorSource::parts));
  CHECK(shown_wall_error(84.26, 1.7, WallErrorSource::parts) == 1.7);
  CHECK(shown_wall_error(-2.0, 0.5, WallErrorSource::parts) == 0.5);
  // From history it is measured where it is defined: shown whatever its size.
  CHECK(shown_wall_error(84.26, 170.0, WallErrorSource::history) == 170.0);
  CHECK_FALSE(shown_wall_error(84.26, std::nullopt, WallErrorSource::history));
  CHECK_FALSE(shown_wall_error(84.26, 1.0, WallErrorSource::none));
  CHECK_FALSE(shown_wall_error(84.26, std::nan(""), WallErrorSource::parts));
}

}  // namespace swarmlab
