// The forces panel (Appendix B's projects): uniform gravity, a hard floor and linear drag.
// Every edit goes through the draft, so a value the preset rules refuse is shown with the
// CLI's message and the running preset carries on.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "i18n/translator.h"
#include "ui/kit/touch_target.h"
#include "ui/panels/panels.h"

namespace swarmlab {
namespace {

/// A floor height just under the draft's particles, for switching the floor on.
double floor_below(const swarm::Preset& p) {
  if (const auto* g = std::get_if<swarm::SwarmSpec>(&p.particles)) return -g->position_radius;
  double lowest = 0;
  bool first = true;
  for (const auto& q : std::get<std::vector<swarm::Particle>>(p.particles)) {
    lowest = first ? q.r.z() : std::min(lowest, q.r.z());
    first = false;
  }
  return lowest - 0.5;
}

/// "0, 3, 5" <-> a list of indices. Anything that is not a whole number >= 0 is refused here
/// with the field's name, as the preset rules would word it.
std::string listed(const std::vector<std::size_t>& indices) {
  std::string out;
  for (std::size_t i : indices) out += (out.empty() ? "" : ", ") + std::to_string(i);
  return out;
}

bool parse_indices(const char* text, std::vector<std::size_t>& out) {
  out.clear();
  const char* p = text;
  while (*p) {
    while (*p == ' ' || *p == ',') ++p;
    if (!*p) break;
    char* end = nullptr;
    const long long v = std::strtoll(p, &end, 10);
    if (end == p || v < 0) return false;
    out.push_back(std::size_t(v));
    p = end;
  }
  return !out.empty();
}

}  // namespace

void draw_forces_panel(AppState& state) {
  swarm::Preset& d = state.draft;
  bool changed = false;
  const float width = 0.6f * ImGui::GetContentRegionAvail().x;

  bool gravity = d.gravity.has_value();
  if (ImGui::Checkbox(tr_id("gravity"), &gravity)) {
    changed = true;
    if (gravity)
      d.gravity = swarm::Vec3(0, 0, -9.8);
    else
      d.gravity.reset();
  }
  help_marker(
      tr("A uniform field g pulling every particle alike: the centre of mass falls like a "
         "thrown ball, R = R0 + V0 t + g t^2 / 2, while the motion about it is unchanged. The "
         "energy E includes the potential energy -sum m g.r."));
  if (d.gravity) {
    double g[3] = {d.gravity->x(), d.gravity->y(), d.gravity->z()};
    ImGui::SetNextItemWidth(width);
    ImGui::InputScalarN(tr_id("g (x, y, z)"), ImGuiDataType_Double, g, 3, nullptr, nullptr, "%.4g");
    if (committed()) {
      d.gravity = swarm::Vec3(g[0], g[1], g[2]);
      changed = true;
    }
  }

  bool floor = d.floor.has_value();
  if (ImGui::Checkbox(tr_id("floor"), &floor)) {
    changed = true;
    if (floor)
      d.floor = swarm::Floor{floor_below(d), 1.0};
    else
      d.floor.reset();
  }
  help_marker(
      tr("A hard horizontal plane z = h. A particle that reaches it moving down leaves with "
         "v_z -> -e v_z (e = restitution: 1 elastic, 0 it stops falling). Each bounce kicks the "
         "centre of mass; the energy an inelastic bounce takes is booked as work."));
  if (d.floor) {
    ImGui::SetNextItemWidth(width);
    changed |= input_double(tr_id("floor height z"), &d.floor->z);
    ImGui::SetNextItemWidth(width);
    changed |= input_double(tr_id("restitution e"), &d.floor->restitution, "%.3g");
  }

  int drag = !d.drag ? 0 : d.drag->mass_proportional() ? 1 : 2;
  ImGui::TextUnformatted(tr("Drag"));
  bool drag_changed = wrapping_radio(tr_id("none"), &drag, 0);
  drag_changed |= wrapping_radio(tr_id("gamma"), &drag, 1);
  drag_changed |= wrapping_radio("b", &drag, 2);
  help_marker(
      tr("gamma: a force -gamma m v on every particle (proportional to its mass): still solved "
         "exactly; the CM velocity decays as exp(-gamma t) and every particle is a damped "
         "oscillator about the CM. b: a force -b v on the listed particles only (indices from "
         "0: the table's #1 is 0): needs a numerical method (Euler, Euler-Cromer, Verlet or "
         "RK4)."));
  if (drag_changed) {
    changed = true;
    if (drag == 0) d.drag.reset();
    if (drag == 1) d.drag = swarm::Drag{0.5, 0, {}};
    if (drag == 2) d.drag = swarm::Drag{0, 0.5, {0}};
  }
  if (d.drag && d.drag->mass_proportional()) {
    ImGui::SetNextItemWidth(width);
    changed |= input_double(tr_id("gamma (1/time)"), &d.drag->gamma);
  } else if (d.drag) {
    ImGui::SetNextItemWidth(width);
    changed |= input_double(tr_id("b (mass/time)"), &d.drag->b);
    std::string& text = state.controls_memory.drag_particles;
    std::string& shown = state.controls_memory.drag_particles_shown;
    if (shown != listed(d.drag->particles)) {
      shown = listed(d.drag->particles);
      text = shown;
    }
    ImGui::SetNextItemWidth(width);
    ImGui::InputText(tr_id("particles"), &text);
    if (committed()) {
      std::vector<std::size_t> indices;
      if (parse_indices(text.c_str(), indices)) {
        d.drag->particles = indices;
        changed = true;
      } else {
        state.draft_error = "drag.particles: must be a list of particle indices, e.g. 0, 3, 5";
        state.draft_error_section = Section::forces;
      }
    }
  }
  if (changed) state.apply_draft(Section::forces);
  show_refusal(state, Section::forces);

  // The books of the running system: what the floor and drag took since t = 0.
  const auto& samples = state.run->primary().samples();
  if ((state.preset.floor || state.preset.drag) && !samples.empty()) {
    ImGui::Separator();
    const swarm::EnergyBooks& b = samples.back().books;
    char text[160];
    std::snprintf(text, sizeof text, tr("work by the floor %.5g, drag loss %.5g"), b.wall_work,
                  b.drag_loss);
    ImGui::TextUnformatted(translator().numbers(text).c_str());
    help_marker(tr("Energy from outside since t = 0: E - E0 = work + heat - drag loss."));
  }
}

}  // namespace swarmlab
