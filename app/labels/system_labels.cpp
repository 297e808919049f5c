#include "labels/system_labels.h"

#include <algorithm>
#include <cstdio>

#include "i18n/translator.h"
#include "swarm/physics/regime.h"

namespace swarmlab::labels {

std::string regime_label(const swarm::Preset& preset) {
  // Whole phrases, so a translation may order the force and the container as its language does.
  if (preset.container_radius)
    return preset.J > 0   ? tr("attractive (J > 0) in a container")
           : preset.J < 0 ? tr("repulsive (J < 0) in a container")
                          : tr("free (J = 0) in a container");
  return preset.J > 0   ? tr("attractive (J > 0), isolated")
         : preset.J < 0 ? tr("repulsive (J < 0), isolated")
                        : tr("free (J = 0), isolated");
}

std::string title(const swarm::Preset& preset, bool edited) {
  // A shipped preset's name is a key of the tables; a user's own shows as written.
  const std::string name = preset.name.empty() ? tr("(unnamed preset)") : tr(preset.name.c_str());
  if (!edited) return name;
  const std::string regime = regime_label(preset);
  const char* format = tr("%s  (edited) \u00b7 now %s");
  // As long as the name needs: a preset from a link may carry any name.
  const int length = std::snprintf(nullptr, 0, format, name.c_str(), regime.c_str());
  std::string text(std::size_t(std::max(length, 0)), '\0');
  std::snprintf(text.data(), text.size() + 1, format, name.c_str(), regime.c_str());
  return text;
}

std::string clock_text(const swarm::Preset& preset, double k, double t) {
  char text[160];
  const bool isolated = !preset.container_radius;
  if (isolated && swarm::regime_of(k) == swarm::Regime::attractive)
    std::snprintf(text, sizeof text, tr("t = %.3f   \u03c9t/2\u03c0 = %.3f"), t,
                  t / swarm::period_of(k));
  else if (isolated && swarm::regime_of(k) == swarm::Regime::repulsive)
    std::snprintf(text, sizeof text, tr("t = %.3f   \u03a9t = %.3f"), t, swarm::omega_of(k) * t);
  else
    std::snprintf(text, sizeof text, tr("t = %.3f"), t);
  return translator().numbers(text);
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
