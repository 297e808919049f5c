#include <cstdio>

#include "cli/cli.h"
#include "lessons/lesson_file.h"
#include "files/text_file.h"

namespace swarmlab {
namespace {

// A lesson file ("lesson": 1) is checked as a lesson, its shipped presets looked up in the
// source tree's assets/presets.
int validate_lesson(const std::string& path, const std::string& text) {
  LessonParse parsed = parse_lesson(text, shipped_preset_lookup(SWARMLAB_PRESET_DIR));
  if (!parsed.lesson) parsed.error = path + ": " + parsed.error;
  if (!parsed.lesson) {
    std::fprintf(stderr, "error: %s\n", parsed.error.c_str());
    return 1;
  }
  const std::size_t steps = parsed.lesson->steps.size();
  std::printf("%s: valid lesson \"%s\" (%zu step%s)\n", path.c_str(), parsed.lesson->id.c_str(),
              steps, steps == 1 ? "" : "s");
  return 0;
}

}  // namespace

int validate_command(const std::string& preset_path) {
  // The file is read once, then checked as a lesson or as a preset.
  std::string read_error;
  const std::string text = read_text_file(preset_path, read_error);
  if (read_error.empty() && looks_like_lesson(text)) return validate_lesson(preset_path, text);
  swarm::PresetParse parsed;
  if (read_error.empty()) {
    parsed = swarm::parse_preset(text);
    if (!parsed.preset) parsed.error = preset_path + ": " + parsed.error;
  } else {
    parsed.error = read_error;
  }
  if (!parsed.preset) {
    std::fprintf(stderr, "error: %s\n", parsed.error.c_str());
    return 1;
  }
  const swarm::Preset& p = *parsed.preset;
  const swarm::RunPlan plan = swarm::run_plan(p);
  std::printf("%s: valid (%s, %ld steps of dt = %g, %s)\n", preset_path.c_str(),
              std::string(swarm::name_of(p.method)).c_str(), plan.steps, p.dt,
              p.container_radius ? "in a container" : "isolated");
  return 0;
}

}  // namespace swarmlab
