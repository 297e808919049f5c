#include "ui/time/time_controls.h"

#include <doctest/doctest.h>

#include <string>

#include "files/preset_file.h"

namespace swarmlab {
namespace {

/// The app's state running a shipped preset (Fig. 1: four masses, 4000 steps).
AppState running(const char* file = "fig1-four-masses.json") {
  AppState state;
  const swarm::PresetParse parsed = read_preset_file(std::string(SWARM_PRESET_DIR) + "/" + file);
  REQUIRE(parsed.preset);
  state.open(*parsed.preset, file);
  return state;
}

/// The positions of the run now, to compare two ways of getting there bit for bit.
std::vector<swarm::Vec3> positions(AppState& state) {
  std::vector<swarm::Vec3> r;
  for (const auto& p : state.run->system().particles) r.push_back(p.r);
  return r;
}

double end_time(const AppState& state) {
  return double(state.run->timeline().end_step()) * state.preset.dt;
}

}  // namespace

TEST_CASE("time controls: the page's seek is refused beyond the run, with the rule") {
  AppState state = running();
  const double end = end_time(state);
  REQUIRE(end > 1);
  CHECK(seek_refusal(state, 0).empty());
  CHECK(seek_refusal(state, end).empty());
  CHECK(seek_refusal(state, 0.5 * end).empty());
  const std::string far = seek_refusal(state, 1e9);
  CHECK(far.find("t = 1000000000") != std::string::npos);  // names the argument
  CHECK(far.find("from 0 to the end of the preset's run") != std::string::npos);  // and the rule
  CHECK_FALSE(seek_refusal(state, -1).empty());
  CHECK_FALSE(seek_refusal(state, end + state.preset.dt).empty());
}

TEST_CASE("time controls: the page's seek goes a budget at a time and ends at its target") {
  AppState state = running();
  const double target = 0.9 * end_time(state);
  const long id = seek_in_frames(state, target);
  CHECK(state.travel.kind == TimeTravel::Kind::to_time);
  CHECK(state.travel.id == id);
  // With no time to spare each frame does one chunk, doubling: many frames, progress rising.
  int frames = 0;
  double progress = 0;
  while (state.travel.active()) {
    continue_travel(state, 1e-9);
    ++frames;
    if (state.travel.active()) {
      const double now = state.travel.progress(state.run->step());
      CHECK(now >= progress);
      progress = now;
    }
    REQUIRE(frames < 100000);
  }
  CHECK(frames > 3);
  REQUIRE(state.travel_ends.size() == 1);
  CHECK(state.travel_ends[0].id == id);
  CHECK(state.travel_ends[0].reached);
  CHECK(state.run->step() == state.run->timeline().step_of(target));
  CHECK(state.travel_ends[0].t == state.run->time());
  CHECK(state.last_fast_forward.reached);  // shown like a fast-forward

  // The same state as a run that went there in one go.
  AppState direct = running();
  direct.run->advance(state.run->step());
  CHECK(positions(direct) == positions(state));
}

TEST_CASE("time controls: a new seek, Play, Cancel or another preset cancels the page's seek") {
  AppState state = running();
  const double end = end_time(state);
  const long first = seek_in_frames(state, end);
  const long second = seek_in_frames(state, 0.5 * end);  // overtakes the first
  REQUIRE(state.travel_ends.size() == 1);
  CHECK(state.travel_ends[0].id == first);
  CHECK_FALSE(state.travel_ends[0].reached);
  state.travel_ends.clear();

  play_or_continue(state);  // Play (or Pause) stops it where it is
  CHECK(state.playing);
  REQUIRE(state.travel_ends.size() == 1);
  CHECK(state.travel_ends[0].id == second);
  CHECK_FALSE(state.travel_ends[0].reached);
  state.travel_ends.clear();

  const long third = seek_in_frames(state, end);
  CHECK_FALSE(state.playing);
  cancel_travel(state);  // Cancel, Esc
  REQUIRE(state.travel_ends.size() == 1);
  CHECK(state.travel_ends[0].id == third);
  CHECK_FALSE(state.travel_ends[0].reached);
  state.travel_ends.clear();

  const long fourth = seek_in_frames(state, end);
  state.restart();  // a preset opened, or the run started again
  REQUIRE(state.travel_ends.size() == 1);
  CHECK(state.travel_ends[0].id == fourth);
  CHECK_FALSE(state.travel_ends[0].reached);
  CHECK_FALSE(state.travel.active());

  // Where the run already is, it ends at once, reached.
  state.travel_ends.clear();
  const long here = seek_in_frames(state, 0);
  REQUIRE(state.travel_ends.size() == 1);
  CHECK(state.travel_ends[0].id == here);
  CHECK(state.travel_ends[0].reached);
}

}  // namespace swarmlab
