// The container panel: the spherical wall, the collision rule, and the stepwise expansion of
// the paper with a button to expand at once.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "i18n/translator.h"
#include "swarm/physics/wall.h"
#include "ui/kit/touch_target.h"
#include "ui/panels/panels.h"

namespace swarmlab {
namespace {

/// A radius that holds the draft's particles, for switching the container on.
double enclosing_radius(const swarm::Preset& p) {
  if (const auto* g = std::get_if<swarm::SwarmSpec>(&p.particles))
    return std::max(1.0, g->position_radius);
  double r = 0;
  for (const auto& q : std::get<std::vector<swarm::Particle>>(p.particles))
    r = std::max(r, q.r.norm());
  return r > 0 ? r * 1.25 : 1.0;
}

/// Switches the stepwise expansion off; the run keeps the length the expansion gave it.
void drop_expansion(swarm::Preset& p) {
  p.duration = p.expansion->tau * double(p.expansion->stages);
  p.expansion.reset();
}

}  // namespace

void draw_container_panel(AppState& state) {
  swarm::Preset& d = state.draft;
  bool changed = false;
  bool enclosed = d.container_radius.has_value();
  if (ImGui::Checkbox(tr_id("spherical container"), &enclosed)) {
    changed = true;
    if (enclosed) {
      d.container_radius = enclosing_radius(d);
    } else {
      d.container_radius.reset();
      if (d.expansion) drop_expansion(d);
    }
  }
  help_marker(
      tr("A sphere about the origin. Particles bounce elastically; the wall measures the "
         "pressure P = sum |dp_r| / (4 pi R^2 t) and the temperature T (half the mean "
         "kinetic energy of the particles that hit it, k_B = 1)."));
  const float width = 0.45f * ImGui::GetContentRegionAvail().x;
  if (d.container_radius) {
    ImGui::SetNextItemWidth(width);
    changed |= input_double(tr_id("radius R"), &*d.container_radius);
    int mode = d.collisions == swarm::CollisionMode::paper ? 0 : 1;
    ImGui::TextUnformatted(tr("Wall hits"));
    changed |= wrapping_radio(tr_id("paper"), &mode, 0);
    changed |= wrapping_radio(tr_id("exact"), &mode, 1);
    d.collisions = mode == 0 ? swarm::CollisionMode::paper : swarm::CollisionMode::exact;
    help_marker(
        tr("paper: Appendix A as written, a particle about to leave is reflected at the start "
           "of the step (first-order error). exact: reflected at the instant it reaches "
           "the wall (analytic method only)."));

    bool expanding = d.expansion.has_value();
    if (ImGui::Checkbox(tr_id("stepwise expansion"), &expanding)) {
      changed = true;
      if (expanding) {
        swarm::ExpansionProtocol e;
        e.stages = 10;
        e.tau = std::max(d.dt * 100, d.duration / 10);
        d.expansion = e;
      } else {
        drop_expansion(d);
      }
    }
    help_marker(
        tr("The paper's protocol: every tau the radius grows by the factor; the first "
           "'thermalise' fraction of each stage is left alone, P and T are averaged over "
           "the rest. Moving the wall does no work, so E stays constant."));
    if (d.expansion) {
      ImGui::SetNextItemWidth(width);
      changed |= input_double(tr_id("factor"), &d.expansion->factor);
      std::int64_t stages = d.expansion->stages;
      ImGui::SetNextItemWidth(width);
      ImGui::InputScalar(tr_id("stages"), ImGuiDataType_S64, &stages);
      d.expansion->stages = long(std::clamp<std::int64_t>(stages, -1, 1'000'000'000));
      changed |= committed();
      ImGui::SetNextItemWidth(width);
      changed |= input_double(tr_id("tau"), &d.expansion->tau);
      ImGui::SetNextItemWidth(width);
      changed |= input_double(tr_id("thermalise"), &d.expansion->thermalize_fraction, "%.3g");
    }
  }
  if (changed) state.apply_draft(Section::container);
  show_refusal(state, Section::container);

  // The live wall, which the expansion (or the button) has moved since the start.
  if (const auto R = state.run->primary().engine().container_radius()) {
    ImGui::Separator();
    const auto& stages = state.run->primary().stages();
    char text[160];
    std::snprintf(text, sizeof text, tr("now: R = %.4g, V = %.4g"), *R, swarm::sphere_volume(*R));
    ImGui::TextUnformatted(translator().numbers(text).c_str());
    if (state.preset.expansion)
      ImGui::Text(tr("stage %zu of %ld"),
                  std::min<std::size_t>(stages.size() + 1, state.preset.expansion->stages),
                  state.preset.expansion->stages);
    const double factor = state.preset.expansion ? state.preset.expansion->factor : 1.1;
    // The factor as it always read (to_string's six decimals cut to five characters), and one
    // ID whatever the factor and the language.
    std::snprintf(text, sizeof text, tr("Expand now (R x %s)"),
                  translator().numbers(std::to_string(factor).substr(0, 5)).c_str());
    const std::string label = std::string(text) + "###Expand now";
    if (ImGui::Button(label.c_str())) state.run->expand_container(factor);
    help_marker(
        tr("Grows the wall of the running system at once (E). Outside the protocol's stages "
           "(a fixed container, or after the last stage) it also ends a stage by hand, "
           "averaged like the protocol's and plotted under Expansion: P-V point by point. "
           "Reset returns to the preset's radius."));
  }
}

}  // namespace swarmlab
