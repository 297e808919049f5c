// The walls-and-spheres panel (Appendix B): a wall that moves in and out on a list of legs, a
// wall held at a temperature, and particles that are hard spheres. Edits go through the draft,
// so a senseless combination shows the core's own message.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "i18n/translator.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/physics/wall_motion.h"
#include "ui/kit/touch_target.h"
#include "ui/panels/panels.h"

namespace swarmlab {
namespace {

enum WallKind { still, moving, hot };

WallKind wall_kind(const swarm::Preset& p) {
  if (!p.wall_moves.empty()) return moving;
  if (p.wall_temperature) return hot;
  return still;
}

/// The draft switched to a kind of wall, with values a student can start from.
void set_wall_kind(swarm::Preset& d, WallKind kind) {
  const double R = d.container_radius.value_or(1.0);
  d.wall_moves.clear();
  d.wall_temperature.reset();
  if (kind == moving) d.wall_moves = {{0.6 * R, 0.1 * R}, {R, 0.1 * R}};
  if (kind == hot) d.wall_temperature = 1.0;
}

bool draw_moves(swarm::Preset& d, float width) {
  bool changed = false;
  std::size_t drop = d.wall_moves.size();
  for (std::size_t i = 0; i < d.wall_moves.size(); ++i) {
    ImGui::PushID(int(i));
    ImGui::Text("%zu.", i + 1);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(0.5f * width);
    changed |= input_double(tr_id("to R"), &d.wall_moves[i].to, "%.4g");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(0.5f * width);
    changed |= input_double(tr_id("at u"), &d.wall_moves[i].speed, "%.4g");
    if (d.wall_moves.size() > 1) {
      ImGui::SameLine();
      if (ImGui::Button("x", ImVec2(target_width("x"), 0))) drop = i;
    }
    ImGui::PopID();
  }
  if (drop < d.wall_moves.size()) {
    d.wall_moves.erase(d.wall_moves.begin() + long(drop));
    changed = true;
  }
  if (ImGui::Button(tr_id("+ move"), ImVec2(target_width(tr_id("+ move")), 0))) {
    const swarm::WallMove last = d.wall_moves.back();
    d.wall_moves.push_back({d.container_radius.value_or(1.0), last.speed});
    changed = true;
  }
  return changed;
}

}  // namespace

void draw_walls_panel(AppState& state) {
  swarm::Preset& d = state.draft;
  bool changed = false;
  const float width = 0.45f * ImGui::GetContentRegionAvail().x;

  if (!d.container_radius) {
    ImGui::TextDisabled("%s", tr("A moving or hot wall needs the container (above)."));
  } else {
    int kind = wall_kind(d);
    ImGui::TextUnformatted(tr("Wall"));
    bool picked = wrapping_radio(tr_id("still"), &kind, still);
    picked |= wrapping_radio(tr_id("moving"), &kind, moving);
    picked |= wrapping_radio(tr_id("hot"), &kind, hot);
    if (picked && kind != wall_kind(d)) {
      set_wall_kind(d, WallKind(kind));
      changed = true;
    }
    help_marker(
        tr("moving: the wall travels to each radius in turn at its speed u, then stays. A "
           "particle bounces off it with its velocity relative to the wall reversed, so "
           "squeezing does work on the gas (W) and letting out takes it back. hot: a particle "
           "that hits the wall is sent back with a random velocity from the Maxwell "
           "distribution at the wall's temperature Tw; the energy it gains is heat (Q)."));
    if (!d.wall_moves.empty()) changed |= draw_moves(d, width);
    if (d.wall_temperature) {
      ImGui::SetNextItemWidth(width);
      changed |= input_double(tr_id("wall temperature Tw"), &*d.wall_temperature, "%.4g");
    }
  }

  bool spheres = d.sphere_radius.has_value();
  if (ImGui::Checkbox(tr_id("hard spheres"), &spheres)) {
    changed = true;
    if (spheres)
      d.sphere_radius = 0.02 * d.container_radius.value_or(1.0);
    else
      d.sphere_radius.reset();
  }
  help_marker(
      tr("Every particle is a ball of radius a; two balls that touch bounce elastically, "
         "sharing energy and momentum, and a ball reaches the wall when its centre is at R - a. "
         "The balls are drawn at their true size."));
  if (d.sphere_radius) {
    ImGui::SetNextItemWidth(width);
    changed |= input_double(tr_id("sphere radius a"), &*d.sphere_radius, "%.4g");
  }
  if (changed) state.apply_draft(Section::walls);
  show_refusal(state, Section::walls);

  // The gas's temperature now and how Maxwellian its speeds are (the energy books, W and Q,
  // are in the plots with the run's samples).
  const swarm::Preset& p = state.preset;
  if (p.wall_moves.empty() && !p.wall_temperature && !p.sphere_radius) return;
  ImGui::Separator();
  const swarm::System& s = state.run->system();
  const swarm::SpeedCheck speeds = swarm::check_speeds(s);
  char text[160];
  std::snprintf(text, sizeof text, tr("gas temperature T = %.4g"), speeds.T);
  ImGui::TextUnformatted(translator().numbers(text).c_str());
  if (p.wall_temperature) {
    std::snprintf(text, sizeof text, tr("wall temperature Tw = %.4g"), *p.wall_temperature);
    ImGui::TextUnformatted(translator().numbers(text).c_str());
  }
  if (speeds.T > 0 && speeds.n >= 20) {
    std::snprintf(text, sizeof text, tr("speeds vs Maxwell: KS sqrt(N) D = %.3g"),
                  std::sqrt(double(speeds.n)) * speeds.ks_distance);
    ImGui::TextUnformatted(translator().numbers(text).c_str());
    help_marker(
        tr("The Kolmogorov-Smirnov distance between the particles' speeds and the Maxwell "
           "distribution at T, times sqrt(N). Below about 1.4 the speeds are as Maxwellian as "
           "a true sample of N would be."));
  }
}

}  // namespace swarmlab
