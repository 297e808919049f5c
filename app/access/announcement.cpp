#include "access/announcement.h"

#include <cstdio>

namespace swarmlab {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);  // as the read-outs show it
  return text;
}

const char* run_state(const Situation& s) {
  return s.finished ? "finished" : s.playing ? "playing" : "paused";
}

/// What, when it changes, is said at once rather than at the next time update.
bool same_events(const Situation& a, const Situation& b) {
  return a.preset == b.preset && a.playing == b.playing && a.finished == b.finished &&
         a.selected == b.selected && a.error == b.error && a.P.has_value() == b.P.has_value();
}

}  // namespace

std::string describe(const Situation& s) {
  std::string text;
  if (!s.error.empty()) text += "Error: " + s.error + ". ";
  text += s.preset.empty() ? "Swarm Lab" : s.preset;
  if (!text.empty() && text.back() != '.') text += '.';
  std::string state = run_state(s);
  state[0] = char(state[0] - 'a' + 'A');
  text += " " + state + ", t = " + number(s.t) + ".";
  if (s.P && s.T) text += " P = " + number(*s.P) + ", T = " + number(*s.T) + ".";
  if (s.selected) text += " Particle " + std::to_string(*s.selected + 1) + " selected.";
  return text;
}

std::string page_title(const Situation& s) {
  return "Swarm Lab \u2014 " + (s.preset.empty() ? std::string("no preset") : s.preset) + ", " +
         run_state(s);
}

std::optional<std::string> Announcer::next(const Situation& now, double wall_seconds) {
  const bool event = !last_ || !same_events(now, *last_);
  const bool new_turn = last_ && now.lesson_turn != last_->lesson_turn;
  const bool lesson_said =
      !now.lesson.empty() && (!last_ || now.lesson_place != last_->lesson_place || new_turn);
  const bool time_due = now.playing && wall_seconds - said_at_ >= kTimeInterval;
  last_ = now;
  if (!event && !lesson_said && !time_due) return std::nullopt;
  std::string text = describe(now);
  if (lesson_said) text = event ? now.lesson + " " + text : now.lesson;
  if (text == said_ && !(lesson_said && new_turn)) return std::nullopt;
  said_ = text;
  said_at_ = wall_seconds;
  return text;
}

}  // namespace swarmlab
