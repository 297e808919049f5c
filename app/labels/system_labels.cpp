#include "labels/system_labels.h"

#include <cstdio>

#include "swarm/physics/regime.h"

namespace swarmlab::labels {

std::string regime_label(const swarm::Preset& preset) {
  std::string force = preset.J > 0   ? "attractive (J > 0)"
                      : preset.J < 0 ? "repulsive (J < 0)"
                                     : "free (J = 0)";
  return force + (preset.container_radius ? " in a container" : ", isolated");
}

std::string title(const swarm::Preset& preset, bool edited) {
  std::string t = preset.name.empty() ? "(unnamed preset)" : preset.name;
  if (edited) t += "  (edited) \u00b7 now " + regime_label(preset);
  return t;
}

std::string clock_text(const swarm::Preset& preset, double k, double t) {
  char text[96];
  const bool isolated = !preset.container_radius;
  if (isolated && swarm::regime_of(k) == swarm::Regime::attractive)
    std::snprintf(text, sizeof text, "t = %.3f   \u03c9t/2\u03c0 = %.3f", t, t / swarm::period_of(k));
  else if (isolated && swarm::regime_of(k) == swarm::Regime::repulsive)
    std::snprintf(text, sizeof text, "t = %.3f   \u03a9t = %.3f", t, swarm::omega_of(k) * t);
  else
    std::snprintf(text, sizeof text, "t = %.3f", t);
  return text;
}

bool differs_from_shipped(const swarm::Preset& opened, const std::vector<swarm::Preset>& shipped) {
  // The name is one of the fields: only a shipped preset of the same name can be equal, and
  // writing out a linked preset of 12,000 particles costs a tenth of a second in the browser.
  std::string text;
  for (const swarm::Preset& s : shipped) {
    if (s.name != opened.name) continue;
    if (text.empty()) text = swarm::preset_to_json(opened);
    if (swarm::preset_to_json(s) == text) return false;
  }
  return true;
}

}  // namespace swarmlab::labels
