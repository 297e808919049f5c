#include "ui/lesson_player/lesson_scene.h"

#include <cmath>

namespace swarmlab {
namespace {

PlotTab plot_tab(LessonPlot plot) {
  switch (plot) {
    case LessonPlot::wall: return PlotTab::wall;
    case LessonPlot::energy: return PlotTab::energy;
    case LessonPlot::expansion: return PlotTab::expansion;
    case LessonPlot::compare: return PlotTab::compare;
    case LessonPlot::particle: return PlotTab::particle;
    case LessonPlot::projects: return PlotTab::projects;
  }
  return PlotTab::wall;
}

SpringOverlay overlay_of(LessonOverlay overlay) {
  switch (overlay) {
    case LessonOverlay::none: return SpringOverlay::off;
    case LessonOverlay::springs: return SpringOverlay::pairs;
    case LessonOverlay::springs_to_cm: return SpringOverlay::to_cm;
  }
  return SpringOverlay::off;
}

}  // namespace

void show_lesson_scene(AppState& app, const LessonScene& scene) {
  if (scene.preset_step) {
    app.open(*scene.preset_step->preset, scene.location);
    app.shipped_id = scene.preset_step->preset_name;
  }
  if (!scene.step) return;
  const LessonStep& s = *scene.step;
  if (s.plot) app.plots.tab = plot_tab(*s.plot);
  if (s.select && *s.select < app.run->system().particles.size()) {
    app.selected = *s.select;
    app.update_followed();
  }
  if (s.overlay) app.view.springs = overlay_of(*s.overlay);
  if (scene.pause) app.playing = false;
}

void open_lesson(AppState& app, const Lesson& lesson) {
  show_lesson_scene(app, app.lessons.open(lesson));
}

std::string open_lesson_json(AppState& app, const std::string& json) {
  LessonScene scene;
  std::string error = app.lessons.open_json(json, &scene);
  if (error.empty()) show_lesson_scene(app, scene);
  return error;
}

std::string open_lesson_id(AppState& app, const std::string& id) {
  LessonScene scene;
  std::string error = app.lessons.open_id(id, &scene);
  if (error.empty()) show_lesson_scene(app, scene);
  return error;
}

std::string open_file_text(AppState& app, const std::string& text, const std::string& location) {
  if (!looks_like_lesson(text)) return app.open_json(text, location);
  std::string error = open_lesson_json(app, text);
  if (error.empty()) app.lessons.dismiss_welcome();
  return error;
}

void keep_lesson_run_going(AppState& app) {
  const LessonStep* s = app.lessons.run_step();
  if (!s || !app.run->finished() || !app.run->primary().failure().empty()) return;
  if (s->run_loop) {
    ++app.lesson_loops;
    app.restart();
    return;
  }
  const double dt = app.preset.dt, t = app.run->time();
  if (s->run_until && t < *s->run_until - 0.5 * dt)
    app.run->extend(long(std::ceil((*s->run_until - t) / dt)));
}

Marking answer_lesson_option(AppState& app, std::size_t option) {
  bool play = false;
  const Marking marking = app.lessons.answer_option(option, &play);
  if (play) app.playing = true;
  return marking;
}

}  // namespace swarmlab
