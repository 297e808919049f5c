#include "access/announcement.h"

#include <cstdio>

#include "i18n/printed.h"
#include "i18n/translator.h"

namespace swarmlab {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);  // as the read-outs show it
  return translator().numbers(text);
}

/// What, when it changes, is said at once rather than at the next time update.
bool same_events(const Situation& a, const Situation& b) {
  return a.preset == b.preset && a.playing == b.playing && a.finished == b.finished &&
         a.selected == b.selected && a.error == b.error && a.P.has_value() == b.P.has_value();
}

}  // namespace

std::string describe(const Situation& s) {
  std::string text;
  // The error itself (the core's or the CLI's words) stays as it was given.
  if (!s.error.empty()) text += printed(tr("Error: %s."), s.error.c_str()) + " ";
  text += s.preset.empty() ? "Swarm Lab" : tr(s.preset.c_str());
  if (!text.empty() && text.back() != '.') text += '.';
  const char* state = s.finished  ? tr("Finished, t = %s.")
                      : s.playing ? tr("Playing, t = %s.")
                                  : tr("Paused, t = %s.");
  text += " " + printed(state, number(s.t).c_str());
  if (s.P && s.T)
    text += " " + printed(tr("P = %s, T = %s."), number(*s.P).c_str(), number(*s.T).c_str());
  if (s.selected) text += " " + printed(tr("Particle %zu selected."), *s.selected + 1);
  return text;
}

std::string page_title(const Situation& s) {
  const char* preset = s.preset.empty() ? tr("no preset") : tr(s.preset.c_str());
  return printed(s.finished  ? tr("Swarm Lab \u2014 %s, finished")
                  : s.playing ? tr("Swarm Lab \u2014 %s, playing")
                              : tr("Swarm Lab \u2014 %s, paused"),
                  preset);
}

std::optional<std::string> Announcer::next(const Situation& now, double wall_seconds) {
  const bool event = !last_ || !same_events(now, *last_);
  const bool new_turn = last_ && now.lesson_turn != last_->lesson_turn;
  const bool lesson_said =
      !now.lesson.empty() && (!last_ || now.lesson_place != last_->lesson_place || new_turn);
  const bool time_due = now.playing && wall_seconds - said_at_ >= kTimeInterval;
  const bool notice_said = !now.notice.empty() && (!last_ || now.notice != last_->notice);
  last_ = now;
  if (!event && !lesson_said && !time_due && !notice_said) return std::nullopt;
  std::string text = describe(now);
  if (lesson_said) text = event ? now.lesson + " " + text : now.lesson;
  if (notice_said) text = event || lesson_said || time_due ? now.notice + " " + text : now.notice;
  if (text == said_ && !(lesson_said && new_turn)) return std::nullopt;
  said_ = text;
  said_at_ = wall_seconds;
  return text;
}

}  // namespace swarmlab
