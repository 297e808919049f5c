#include "ui/classroom/classroom_outputs.h"

#include <algorithm>
#include <cstdio>

#include "i18n/translator.h"

#include "ui/kit/theme_style.h"
#include "ui/lesson_player/input_kind.h"
#include "ui/lesson_player/lesson_speech.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace swarmlab {
namespace {

#ifdef __EMSCRIPTEN__
// The page's live region (web/shell.html, #announcer) and title.
// The same words twice (feedback to a second try) end in a no-break space the second time:
// a live region reads a change of its text only.
EM_JS(void, web_announce, (const char* text), {
  var region = document.getElementById('announcer');
  if (!region) return;
  var words = UTF8ToString(text);
  region.textContent = region.textContent === words ? words + '\u00a0' : words;
});
EM_JS(void, web_set_title, (const char* text), { document.title = UTF8ToString(text); });
// The Fullscreen API; a refusal (no gesture, not allowed) is remembered for the next frame.
EM_JS(void, web_request_fullscreen, (int on), {
  try {
    if (on) {
      var root = document.documentElement;
      var asked = root.requestFullscreen ? root.requestFullscreen() : null;
      if (!asked) Module.swarmlabFullscreenRefused = true;
      else if (asked.catch) asked.catch(function() { Module.swarmlabFullscreenRefused = true; });
    } else if (document.fullscreenElement && document.exitFullscreen) {
      document.exitFullscreen().catch(function() {});
    }
  } catch (e) {
    Module.swarmlabFullscreenRefused = true;
  }
});
EM_JS(int, web_fullscreen_refused, (), {
  var refused = Module.swarmlabFullscreenRefused ? 1 : 0;
  Module.swarmlabFullscreenRefused = false;
  return refused;
});
EM_JS(int, web_is_fullscreen, (), { return document.fullscreenElement ? 1 : 0; });
#endif

}  // namespace

Situation situation_of(AppState& state) {
  Situation s;
  s.preset = state.preset.name;
  s.playing = state.playing;
  s.finished = state.run->finished();
  s.t = state.run->time();
  const swarm::WallEstimate& wall = state.instruments.wall;
  if (state.preset.container_radius && wall.intervals > 0) {
    // The read-outs' P and T (over the plots' averaging window), not the last sampling
    // interval's, which at the end of a run may hold no wall hit at all.
    s.P = wall.mean.P;
    if (wall.mean.hits > 0) s.T = wall.mean.T;
  }
  s.selected = state.selected;
  if (state.status_is_error) s.error = state.status;
  s.notice = state.lessons.progress_notice();
  const LessonSpeech speech = lesson_speech(state.lessons, input_kind(state));
  s.lesson = speech.words;
  s.lesson_place = speech.place;
  s.lesson_turn = speech.turn;
  return s;
}

void ClassroomOutputs::apply_theme(AppState& state) {
  if (state.presentation.theme == theme_) return;
  theme_ = state.presentation.theme;
  apply_style(state.layout.ui_scale, theme_);
}

void ClassroomOutputs::update(AppState& state, SDL_Window* window, double seconds) {
  update_fullscreen(state, window);
  wall_seconds_ += seconds;
  const Situation now = situation_of(state);
  if (const auto text = announcer_.next(now, wall_seconds_)) {
#ifdef __EMSCRIPTEN__
    web_announce(text->c_str());
#endif
  }
  const std::string title = page_title(now);
  if (title != title_) {
    title_ = title;
#ifdef __EMSCRIPTEN__
    web_set_title(title.c_str());
#else
    SDL_SetWindowTitle(window, title.c_str());
#endif
  }
  update_sound(state, seconds);
}

void ClassroomOutputs::update_fullscreen(AppState& state, SDL_Window* window) {
  Presentation& p = state.presentation;
#ifdef __EMSCRIPTEN__
  (void)window;
  if (p.fullscreen_wanted != fullscreen_requested_) {
    fullscreen_requested_ = p.fullscreen_wanted;
    fullscreen_seen_ = false;
    web_request_fullscreen(fullscreen_requested_);
  }
  if (web_fullscreen_refused()) {
    state.status = tr("Fullscreen was refused by the browser (use its own fullscreen key, F11)");
    state.status_is_error = true;
    p.fullscreen_wanted = fullscreen_requested_ = false;
  }
  p.fullscreen = web_is_fullscreen() != 0;
#else
  if (p.fullscreen_wanted != fullscreen_requested_) {
    fullscreen_requested_ = p.fullscreen_wanted;
    fullscreen_seen_ = false;
    if (SDL_SetWindowFullscreen(window, p.fullscreen_wanted ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0) !=
        0) {
      char text[600];
      std::snprintf(text, sizeof text, tr("Fullscreen failed: %s"), SDL_GetError());
      state.status = text;
      state.status_is_error = true;
      p.fullscreen_wanted = fullscreen_requested_ = false;
    }
  }
  p.fullscreen = (SDL_GetWindowFlags(window) & SDL_WINDOW_FULLSCREEN) != 0;
#endif
  // Left by other means (Esc in the browser, the window manager): the switch follows.
  if (p.fullscreen) fullscreen_seen_ = true;
  if (fullscreen_seen_ && !p.fullscreen && fullscreen_requested_)
    p.fullscreen_wanted = fullscreen_requested_ = fullscreen_seen_ = false;
}

void ClassroomOutputs::update_sound(AppState& state, double seconds) {
  Presentation& p = state.presentation;
  if (p.sound && !sound_.is_open()) {
    p.sound_status = sound_.open();
    if (!p.sound_status.empty()) {
      p.sound = false;
      state.status = p.sound_status;
      state.status_is_error = true;
    }
    clicks_.reset();
    tally_ = {};
    run_id_ = -1;
  } else if (!p.sound && sound_.is_open()) {
    sound_.close();
  }
  if (!sound_.is_open()) return;
  const std::int64_t hits = state.run->primary().summary().wall_hits;
  if (state.run->id() != run_id_) {
    // A new run: its hits start from zero, and nothing was heard of it yet.
    run_id_ = state.run->id();
    hits_ = hits;
    clicks_.reset();
    return;
  }
  // Going back on the timeline lowers the run's count: no hits were made.
  const std::int64_t new_hits = std::max<std::int64_t>(0, hits - hits_);
  const int n = clicks_.clicks(new_hits, seconds);
  tally_.hits += new_hits;
  tally_.seconds += seconds;
  hits_ = hits;
  if (n > 0) (sound_.play(n, seconds) ? tally_.clicks_played : tally_.clicks_dropped) += n;
}

}  // namespace swarmlab
