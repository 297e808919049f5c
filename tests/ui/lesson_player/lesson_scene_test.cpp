#include "ui/lesson_player/lesson_scene.h"

#include <doctest/doctest.h>

#include <string>

#include "lessons/lesson_file.h"

namespace swarmlab {
namespace {

/// The app's state with the shipped lessons and the lesson `id` open, as the window has it.
AppState with_lesson(const std::string& id) {
  AppState app;
  app.lessons.load(SWARM_LESSON_DIR, make_memory_progress_store(),
                   shipped_preset_lookup(SWARM_PRESET_DIR));
  REQUIRE(open_lesson_id(app, id).empty());
  return app;
}

/// Plays as the window does: advance, then keep the lesson's run going while it plays.
void play_steps(AppState& app, long steps) {
  for (long k = 0; k < steps && app.playing; ++k) {
    app.run->advance(1);
    if (app.playing) keep_lesson_run_going(app);
    if (app.run->finished()) app.playing = false;
  }
}

}  // namespace

TEST_CASE("lesson scene: a step's run with \"until\" goes on past its preset's end") {
  // Lesson 1 opens the pair (its preset ends at t = 8.9) with "run": {"until": 1000}.
  AppState app = with_lesson("one-period");
  REQUIRE(app.lessons.step() == 0);
  const double end = app.preset.duration, dt = app.preset.dt;
  REQUIRE(end < 20);
  app.playing = true;
  play_steps(app, long((end + 5) / dt));
  CHECK(app.playing);
  CHECK(app.run->time() > end + 5 - 2 * dt);
  // Step 2 keeps the scene, so the rule of step 1 still holds there.
  show_lesson_scene(app, app.lessons.next());
  CHECK(app.lessons.run_step() == &app.lessons.open_lesson()->steps[0]);
}

TEST_CASE("lesson scene: a step's run with \"loop\" starts again when it ends") {
  // Lesson 3 opens four masses pushing apart (ends at t = 2) with "run": {"loop": true}; its
  // prediction pauses the run until it is made.
  AppState app = with_lesson("repulsive-runaway");
  CHECK_FALSE(app.playing);
  answer_lesson_option(app, 2);
  REQUIRE(app.playing);
  const long steps = swarm::step_count(app.preset);
  play_steps(app, steps + 10);
  CHECK(app.playing);
  CHECK(app.run->time() == doctest::Approx(10 * app.preset.dt).epsilon(1e-6));
}

TEST_CASE("lesson scene: without a run rule the run ends at its preset's end") {
  AppState app = with_lesson("one-period");
  const std::string plain =
      R"({"lesson": 1, "id": "plain", "title": "Plain", "summary": "No run rule.", "steps": [)"
      R"({"text": "The pair.", "preset": "two-body-circular.json"}]})";
  REQUIRE(open_lesson_json(app, plain).empty());
  REQUIRE(app.lessons.run_step() == nullptr);
  app.playing = true;
  play_steps(app, swarm::step_count(app.preset) + 10);
  CHECK_FALSE(app.playing);
  CHECK(app.run->finished());
  CHECK(app.run->time() == doctest::Approx(app.preset.duration).epsilon(1e-3));
}

TEST_CASE("lesson scene: a file opens as a lesson when it is one, else as a preset") {
  AppState app = with_lesson("one-period");
  const std::string lesson =
      R"({"lesson": 1, "id": "from-a-file", "title": "From a file", "summary": "Opened by path.",)"
      R"( "steps": [{"text": "The pair.", "preset": "two-body-circular.json"}]})";
  // A lesson file is a lesson (not a preset with the unknown keys "id" and "lesson").
  CHECK(open_file_text(app, lesson, "my-lesson.json") == "");
  REQUIRE(app.lessons.open_lesson());
  CHECK(app.lessons.open_lesson()->id == "from-a-file");
  // A broken one gets the lesson's message; the open lesson stays.
  const std::string broken = R"({"lesson": 1, "id": "broken", "title": "\u202e", "summary": "S",)"
                             R"( "steps": [{"text": "a", "preset": "two-body-circular.json"}]})";
  CHECK(open_file_text(app, broken, "broken.json") ==
        "title: must show something (it holds only spaces or invisible characters such as U+202E)");
  CHECK(app.lessons.open_lesson()->id == "from-a-file");
  // A preset file runs as a preset, under the name it was opened from.
  const std::string preset = R"({"name": "From a file", "J": 1, "particles": [{"m": 1, "r": [1, 0, 0],)"
                             R"( "v": [0, 1, 0]}, {"m": 1, "r": [-1, 0, 0], "v": [0, -1, 0]}], "dt": 0.01, "duration": 5})";
  CHECK(open_file_text(app, preset, "pair.json") == "");
  CHECK(app.preset.name == "From a file");
  CHECK(app.location == "pair.json");
  CHECK(open_file_text(app, "{\"J\": 1,", "cut.json").rfind("preset: not valid JSON at line 1, column 9: ", 0) == 0);
}

}  // namespace swarmlab
