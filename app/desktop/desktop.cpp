// The desktop entry point: a window, the shipped presets from disk, and the frame loop; with
// --frames a fixed number of frames, a timing summary and optionally a screenshot.

#include "desktop/desktop.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "desktop/screenshot.h"
#include "files/atomic_file.h"
#include "files/text_file.h"
#include "i18n/language.h"
#include "lessons/lesson_file.h"
#include "ui/classroom/presentation.h"
#include "ui/gl_context_life.h"
#include "ui/lesson_player/lesson_scene.h"
#include "ui/main_loop.h"
#include "ui/parallel_dom/items_json.h"
#include "ui/parallel_dom/parallel_dom.h"
#include "ui/platform/language_memory.h"
#include "ui/state/preset_store.h"

namespace swarmlab {
namespace {

/// Shipped files (presets, lessons): in the source tree of this build, else in the folder
/// `name` next to the binary.
std::string shipped_directory(const char* in_source_tree, const char* name) {
  if (std::filesystem::is_directory(in_source_tree)) return in_source_tree;
  std::string beside;
  if (char* base = SDL_GetBasePath()) {
    beside = std::string(base) + name;
    SDL_free(base);
  }
  return beside;
}
std::string shipped_preset_directory() { return shipped_directory(SWARMLAB_PRESET_DIR, "presets"); }
std::string shipped_lesson_directory() { return shipped_directory(SWARMLAB_LESSON_DIR, "lessons"); }

std::string screenshot_error;
std::string screenshot_path;

void take_screenshot(Frontend& f) {
  int width = 0, height = 0;
  SDL_GL_GetDrawableSize(f.window.window, &width, &height);
  screenshot_error = save_screenshot(screenshot_path, width, height);
}

/// The mirrored items after each frame, numbered, written whole (renamed into place) so a
/// reader never sees half a frame's items; a test that sees an item at the same place in two
/// frames knows it has stopped moving (as Playwright does before a click), and so does one
/// that reads `still`: the window idles after this frame until something changes.
void write_items(const std::string& path, long long frame, bool touch, bool still) {
  const std::string text = "{\"frame\": " + std::to_string(frame) +
                           ", \"still\": " + (still ? "true" : "false") +
                           ", \"dom\": " + items_json(parallel_dom(), touch) + "}";
  if (const std::string e = write_file_atomically(path, text); !e.empty())
    std::fprintf(stderr, "error: %s\n", e.c_str());
}

}  // namespace

int run_desktop(const DesktopOptions& options) {
  // A screenshot that cannot be written is refused before the window opens, not after the run.
  for (const std::string* path : {&options.screenshot_path, &options.items_path})
    if (!path->empty())
      if (const std::string e = check_output_path(*path); !e.empty()) {
        std::fprintf(stderr, "error: %s\n", e.c_str());
        return 1;
      }
  if (!options.language.empty() && !find_language(options.language)) {
    std::fprintf(stderr, "error: --lang: \"%s\" is not a language Swarm Lab speaks (%s)\n",
                 options.language.c_str(), language_codes().c_str());
    return 2;
  }
  std::string error;
  Frontend f;
  f.window = open_window("Swarm Lab", 1280, 720, error);
  if (!f.window.window) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  // A lesson file (swarmlab LESSON.json) opens as a lesson over the default preset.
  std::string lesson_text, lesson_read_error;
  if (!options.preset_path.empty()) {
    lesson_text = read_text_file(options.preset_path, lesson_read_error);
    if (!looks_like_lesson(lesson_text)) lesson_text.clear();
  }
  f.app = std::make_unique<App>(make_file_preset_store(shipped_preset_directory()),
                                lesson_text.empty() ? options.preset_path : "", options.frames > 0);
  // Lessons: shipped beside the presets; progress in the user's config folder, except in
  // scripted runs (--frames), which leave it alone and show no welcome.
  f.app->state().lessons.load(
      shipped_lesson_directory(),
      options.frames > 0 ? make_memory_progress_store() : make_file_progress_store(),
      shipped_preset_lookup(shipped_preset_directory()));
  if (options.frames > 0) f.app->state().lessons.dismiss_welcome();
  if (!lesson_text.empty()) {
    const std::string e = open_lesson_json(f.app->state(), lesson_text);
    if (!e.empty()) {
      std::fprintf(stderr, "error: %s: %s\n", options.preset_path.c_str(), e.c_str());
      f.app.reset();
      close_window(f.window);
      return 1;
    }
    f.app->state().lessons.dismiss_welcome();
    if (options.lesson_summary) f.app->state().lessons.finish();
  }
  if (!f.app->error().empty()) {
    std::fprintf(stderr, "error: %s\n", f.app->error().c_str());
    f.app.reset();
    close_window(f.window);
    return 1;
  }
  if (options.threads > 0) {
    f.app->state().engine_threads = options.threads;
    f.app->state().restart();
  }
  if (options.select > 0) {
    // Selected as by a click, with its x(t) plot open (the instruments' screenshot).
    const std::size_t n = f.app->state().run->system().particles.size();
    if (!f.app->state().select_particle(std::size_t(options.select - 1))) {
      std::fprintf(stderr, "error: --select: must be in [1, %zu] (the preset has %zu particles)\n",
                   n, n);
      f.app.reset();
      close_window(f.window);
      return 1;
    }
    f.app->state().plots.tab = PlotTab::particle;
  }
  if (options.plot_tab > 0) f.app->state().plots.tab = plot_tab_numbered(options.plot_tab);
  if (options.presentation) set_presentation(f.app->state(), true);
  // The language: asked for, else English in scripted runs (screenshots the same on every
  // machine), else the one chosen last or the system's. Only a choice in the app is remembered.
  LanguageChoice& language = f.app->state().language;
  language.remember = options.frames == 0;
  if (!options.language.empty())
    language.pending = options.language;
  else if (options.frames == 0)
    language.pending = startup_language();
  if (options.sound) f.app->state().presentation.sound = true;

  // The first frames build fonts and buffers; the timing summary leaves them out.
  constexpr int kWarmUp = 5;
  double timed_ms = 0, timed_cpu_ms = 0;
  int timed_frames = 0;
  for (int frame = 1; f.running; ++frame) {
    hold_while_minimised(f);  // nothing drawn while nothing can be seen (ui/gl_context_life.h)
    // Paused and still, the window waits for an event (or a caret's blink) instead of drawing;
    // a scripted run draws every one of its frames.
    if (options.frames == 0 && !frame_wanted(f)) {
      const double wait_ms = 1000 * f.demand.seconds_to_next(steady_seconds());
      SDL_WaitEventTimeout(nullptr, int(std::clamp(wait_ms, 1.0, 500.0)));
      --frame;
      continue;
    }
    const bool last = options.frames > 0 && frame == options.frames;
    screenshot_path = options.screenshot_path;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    run_frame(f, last && !screenshot_path.empty() ? take_screenshot : nullptr);
    if (!options.items_path.empty())
      write_items(options.items_path, frame, f.app->state().layout.touch,
                  !f.demand.wanted(steady_seconds()));
    if (frame > kWarmUp) {
      timed_ms +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      timed_cpu_ms += 1000.0 * double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
      ++timed_frames;
    }
    if (last) break;
  }

  int status = 0;
  if (options.frames > 0) {
    const FrameStats& stats = f.app->state().stats;
    // CPU time counts every thread of the process (Mesa's llvmpipe renders on several), so
    // it measures the frame's cost even while other programs share the cores.
    const int n = std::max(timed_frames, 1);
    std::printf(
        "swarmlab: %d frames, %zu particles, mean frame time %.2f ms wall, %.2f ms CPU (of "
        "which stepping %.2f ms, particle colours and sizes %.2f ms)\n",
        options.frames, f.app->state().run->system().particles.size(), timed_ms / n,
        timed_cpu_ms / n, stats.simulation_ms, stats.scene_ms);
    if (const auto& track = f.app->state().instruments.track; track && track->meter.period())
      std::printf("swarmlab: particle %zu: measured period %.6g, formula %.6g\n",
                  track->particle + 1, *track->meter.period(), *track->meter.formula_period());
    if (const auto& sound = f.outputs.sound_tally(); f.app->state().presentation.sound)
      std::printf(
          "swarmlab: sound: %lld clicks played, %lld dropped, for %lld wall hits in %.3f s\n",
          (long long)sound.clicks_played, (long long)sound.clicks_dropped,
          (long long)sound.hits, sound.seconds);
    if (!options.screenshot_path.empty()) {
      if (screenshot_error.empty()) {
        std::printf("swarmlab: screenshot written to %s\n", options.screenshot_path.c_str());
      } else {
        std::fprintf(stderr, "error: %s\n", screenshot_error.c_str());
        status = 1;
      }
    }
  }
  f.app.reset();  // GL objects go before the context
  close_window(f.window);
  return status;
}

}  // namespace swarmlab
