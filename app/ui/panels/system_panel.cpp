// The system panel: the particles (a generated swarm or a table of up to 20), their masses and
// initial conditions, and the coupling J with its sign.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "i18n/translator.h"
#include "swarm/physics/regime.h"
#include "swarm/physics/system.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/touch_target.h"
#include "ui/panels/panels.h"
#include "ui/parallel_dom/item_tooltip.h"

namespace swarmlab {
namespace {

/// A vector's three components side by side, each typed like any other number (so a touch
/// screen brings up its on-screen keyboard for them too).
bool input_vec3(const char* id, swarm::Vec3& v, const char* quantity, std::size_t particle) {
  ImGui::PushID(id);
  const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
  const float width = (ImGui::GetContentRegionAvail().x - 2 * spacing) / 3;
  bool changed = false;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) ImGui::SameLine(0, spacing);
    ImGui::SetNextItemWidth(width);
    ImGui::PushID(k);
    changed |= input_double("##c", &v[k], "%.3g");
    char name[128];
    std::snprintf(name, sizeof name, tr("%s %c of particle %zu"), quantity, "xyz"[k], particle);
    name_item(name);
    ImGui::PopID();
  }
  ImGui::PopID();
  return changed;
}

constexpr std::size_t kTableLimit = 20;
/// Rows a particle table submits whether in view or not (a preset may list far more than the
/// table lets one add).
constexpr std::size_t kRowsAlwaysSubmitted = 64;
constexpr double kMinJ = 1e-6, kMaxJ = 100;  // slider range of |J|; any value can be typed

using ParticleList = std::vector<swarm::Particle>;

void draw_coupling(AppState& state) {
  swarm::Preset& d = state.draft;
  ImGui::TextUnformatted(tr("Coupling J"));
  help_marker(
      tr("Every pair pulls (J > 0) or pushes (J < 0) with F = -J m1 m2 r. Summed over the partners "
         "this is one spring k_i = J M m_i to the centre of mass: all particles share "
         "omega = sqrt(J M) (J > 0) or run away as exp(Omega t), Omega = sqrt(-J M) (J < 0)."));
  // The magnitude survives a trip through J = 0, so "zero" and back restores the old value.
  double& magnitude = state.controls_memory.coupling_magnitude;
  if (d.J != 0) magnitude = std::abs(d.J);
  int sign = d.J > 0 ? 0 : d.J == 0 ? 1 : 2;
  bool changed = false;
  changed |= ImGui::RadioButton(tr_id("attractive"), &sign, 0);
  changed |= wrapping_radio(tr_id("zero"), &sign, 1);
  changed |= wrapping_radio(tr_id("repulsive"), &sign, 2);
  if (changed) d.J = sign == 0 ? magnitude : sign == 1 ? 0.0 : -magnitude;

  double shown = std::abs(d.J);
  ImGui::BeginDisabled(sign == 1);
  ImGui::SetNextItemWidth(-4.5f * ImGui::GetFontSize());
  if (ImGui::SliderScalar("|J|", ImGuiDataType_Double, &shown, &kMinJ, &kMaxJ, "%.3g",
                          ImGuiSliderFlags_Logarithmic))
    d.J = sign == 2 ? -shown : shown;
  changed |= committed();
  ImGui::EndDisabled();
  ImGui::SetNextItemWidth(-4.5f * ImGui::GetFontSize());
  changed |= input_double(tr_id("J (typed)"), &d.J);
  if (changed) state.apply_draft(Section::system);
}

void draw_table(AppState& state, ParticleList& list) {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
  bool changed = false;
  std::optional<std::size_t> remove;
  // Narrow side padding in the cells, and m as wide as "0.000": in a 350 px panel the digits
  // need every pixel (m = 0.25 once showed as "0.2").
  const float font = ImGui::GetFontSize();
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding,
                      ImVec2(0.15f * font, ImGui::GetStyle().FramePadding.y));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemInnerSpacing, ImVec2(0.15f * font, 0.15f * font));
  ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(0.15f * font, 0.15f * font));
  ImGui::PushTextWrapPos(-1.0f);  // cells fit their text (panel_windows.cpp wraps the rest)
  if (ImGui::BeginTable("particles", 4, flags)) {
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("m", ImGuiTableColumnFlags_WidthFixed,
                            ImGui::CalcTextSize("0.000").x + 0.4f * font);
    ImGui::TableSetupColumn("r (x, y, z)", ImGuiTableColumnFlags_WidthStretch, 2.5f);
    ImGui::TableSetupColumn("v (x, y, z)", ImGuiTableColumnFlags_WidthStretch, 2.5f);
    ImGui::TableHeadersRow();
    const auto row = [&](std::size_t i) {
      ImGui::PushID(int(i));
      ImGui::TableNextRow();
      // The selected particle's row stands out, as its card does among the instruments.
      if (state.selected == i)
        ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1,
                               palette(state.presentation.theme).selected_row.packed());
      ImGui::TableNextColumn();
      if (ImGui::Button("x", ImVec2(target_width("x"), 0))) remove = i;
      item_tooltip(tr("Remove particle %zu"), i + 1);
      ImGui::SameLine();
      ImGui::Text("%zu", i + 1);
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-1);
      changed |= input_double("##m", &list[i].m, "%.4g");
      char name[128];
      std::snprintf(name, sizeof name, tr("m of particle %zu"), i + 1);
      name_item(name);
      ImGui::TableNextColumn();
      changed |= input_vec3("##r", list[i].r, "r", i + 1);
      ImGui::TableNextColumn();
      changed |= input_vec3("##v", list[i].v, "v", i + 1);
      ImGui::PopID();
    };
    // A short table submits every row, so that Tab and a screen reader reach each one (the
    // parallel DOM mirrors what is submitted); a long one (a 12,000-particle preset from a
    // link) only the rows in view, or it would cost seconds a frame.
    if (list.size() <= kRowsAlwaysSubmitted) {
      for (std::size_t i = 0; i < list.size(); ++i) row(i);
    } else {
      ImGuiListClipper clipper;
      clipper.Begin(int(list.size()));
      while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) row(std::size_t(i));
    }
    ImGui::EndTable();
  }
  ImGui::PopTextWrapPos();

  ImGui::PopStyleVar(3);
  if (remove && list.size() > 1) {
    list.erase(list.begin() + std::ptrdiff_t(*remove));
    changed = true;
  }
  if (list.size() < kTableLimit && ImGui::Button(tr_id("Add particle"))) {
    // A new particle starts at rest beside the last one, so the system stays compact.
    swarm::Particle p = list.back();
    p.r += swarm::Vec3(0.5, 0.5, 0.0);
    p.v.setZero();
    list.push_back(p);
    changed = true;
  }
  if (changed) state.apply_draft(Section::system);
}

void draw_generator(AppState& state, swarm::SwarmSpec& g) {
  bool changed = false;
  // 64 bits on every platform (long is 32 bits in WebAssembly).
  std::int64_t count = g.count;
  const std::int64_t lo = 1, hi = 100'000;
  ImGui::SetNextItemWidth(-4.5f * ImGui::GetFontSize());
  ImGui::SliderScalar("N", ImGuiDataType_S64, &count, &lo, &hi, "%lld",
                      ImGuiSliderFlags_Logarithmic);
  g.count = long(std::clamp<std::int64_t>(count, 1, 1'000'000'000));
  changed |= committed();
  help_marker(
      tr("Number of particles. Ctrl+click the slider to type any value (up to 10 million); "
         "the analytic method costs O(N) per step, the numerical ones O(N^2)."));

  int mass_kind = g.mass_min == g.mass_max ? 0 : 1;
  ImGui::TextUnformatted(tr("Masses"));
  if (wrapping_radio(tr_id("equal"), &mass_kind, 0)) g.mass_max = g.mass_min, changed = true;
  if (wrapping_radio(tr_id("uniform in [a, b]"), &mass_kind, 1) && g.mass_max == g.mass_min)
    g.mass_max = g.mass_min * 1.25, changed = true;
  const float half = 0.5f * (ImGui::GetContentRegionAvail().x - 2 * ImGui::GetFontSize());
  if (mass_kind == 0) {
    ImGui::SetNextItemWidth(half);
    if (input_double("m", &g.mass_min)) g.mass_max = g.mass_min, changed = true;
  } else {
    ImGui::SetNextItemWidth(half);
    changed |= input_double("a", &g.mass_min);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(half);
    changed |= input_double("b", &g.mass_max);
  }

  ImGui::SetNextItemWidth(half);
  changed |= input_double(tr_id("initial radius"), &g.position_radius);
  help_marker(tr("Positions are drawn uniformly in a ball of this radius about the origin."));
  int velocity_kind = g.velocities == swarm::SwarmSpec::Velocities::ball ? 0 : 1;
  ImGui::TextUnformatted(tr("Velocities"));
  changed |= wrapping_radio(tr_id("uniform ball"), &velocity_kind, 0);
  changed |= wrapping_radio(tr_id("Maxwellian"), &velocity_kind, 1);
  g.velocities = velocity_kind == 0 ? swarm::SwarmSpec::Velocities::ball
                                    : swarm::SwarmSpec::Velocities::maxwell;
  ImGui::SetNextItemWidth(half);
  if (velocity_kind == 0)
    changed |= input_double(tr_id("max speed"), &g.speed);
  else
    changed |= input_double(tr_id("temperature"), &g.temperature);
  changed |= ImGui::Checkbox(tr_id("centre of mass at rest"), &g.cm_at_rest);

  ImGui::SetNextItemWidth(half);
  ImGui::InputScalar(tr_id("seed"), ImGuiDataType_U64, &g.seed);
  changed |= committed();
  ImGui::SameLine();
  if (ImGui::Button(tr_id("New seed"))) {
    g.seed = g.seed * 6364136223846793005ull + 1442695040888963407ull;
    g.seed %= (1ull << 53);  // the preset format keeps seeds exact in a double
    changed = true;
  }
  help_marker(tr("The same seed gives the same swarm on every machine and in the browser."));
  if (changed) state.apply_draft(Section::system);
}

}  // namespace

void draw_system_panel(AppState& state) {
  swarm::Preset& d = state.draft;
  int kind = std::holds_alternative<ParticleList>(d.particles) ? 1 : 0;
  const swarm::System& running = state.run->system();
  const bool small = running.particles.size() <= kTableLimit;
  ImGui::RadioButton(tr_id("generated swarm"), &kind, 0);
  if (ImGui::IsItemClicked() && std::holds_alternative<ParticleList>(d.particles)) {
    swarm::SwarmSpec g;
    g.count = long(std::get<ParticleList>(d.particles).size());
    d.particles = g;
    state.apply_draft(Section::system);
  }
  same_line_if_fits(radio_width(tr_id("particle table")));
  ImGui::BeginDisabled(!small && !std::holds_alternative<ParticleList>(d.particles));
  ImGui::RadioButton(tr_id("particle table"), &kind, 1);
  if (ImGui::IsItemClicked() && std::holds_alternative<swarm::SwarmSpec>(d.particles)) {
    // The table starts from the swarm as generated, so nothing jumps.
    d.particles = swarm::initial_system(state.preset).particles;
    state.apply_draft(Section::system);
  }
  ImGui::EndDisabled();
  help_marker(
      tr("A table lists every particle's m, r and v (up to 20 particles). A generated "
         "swarm is drawn at random from a seed."));

  if (auto* list = std::get_if<ParticleList>(&d.particles))
    draw_table(state, *list);
  else
    draw_generator(state, std::get<swarm::SwarmSpec>(d.particles));
  ImGui::Separator();
  draw_coupling(state);
  show_refusal(state, Section::system);
}

}  // namespace swarmlab
