// The selected particle's card: its mass, where it is and how fast it moves relative to the
// centre of mass, its own energy and the orbit it is on (swarm::particle_orbit).

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include "i18n/translator.h"
#include "swarm/physics/particle_orbit.h"
#include "swarm/physics/system.h"
#include "ui/lesson_player/lesson_panel.h"
#include "ui/panels/panels.h"

namespace swarmlab {
namespace {

void row(const char* name, const std::string& value, const char* meaning) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  bool hovered = ImGui::IsItemHovered();
  ImGui::TableNextColumn();
  ImGui::PushTextWrapPos(0);  // a long value (a translation's sentence) wraps in its column
  ImGui::TextUnformatted(value.c_str());
  ImGui::PopTextWrapPos();
  hovered |= ImGui::IsItemHovered();
  if (hovered) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 26);
    ImGui::TextUnformatted(meaning);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

/// A value printed with `format`, with the language's decimal separator.
std::string number(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return translator().numbers(text);
}

/// Values put into a translated format ("%s about R"), as long as it needs.
std::string sentence(const char* format, const std::string& a, const std::string& b) {
  const int length = std::snprintf(nullptr, 0, format, a.c_str(), b.c_str());
  std::string text(std::size_t(std::max(length, 0)), '\0');
  std::snprintf(text.data(), text.size() + 1, format, a.c_str(), b.c_str());
  return text;
}

}  // namespace

void draw_particle_card(AppState& state) {
  const swarm::System& s = state.run->system();
  if (!state.selected || *state.selected >= s.particles.size()) return;
  const std::size_t i = *state.selected;
  const swarm::ParticleOrbit o = swarm::particle_orbit(
      s.particles[i], swarm::cm_position(s), swarm::cm_velocity(s), swarm::stiffness(s));
  char title[96];
  std::snprintf(title, sizeof title, tr("Particle %zu"), i + 1);
  std::strncat(title, "###particle_card", sizeof title - std::strlen(title) - 1);
  if (!ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (draw_hidden_by_lesson(state, LessonHidden::card)) return;
  const ImGuiTableFlags flags = ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_NoSavedSettings;
  // The names as wide as they are (not wrapped), the values in the rest of the width.
  ImGui::PushTextWrapPos(-1.0f);
  if (!ImGui::BeginTable("particle_card", 2, flags)) {
    ImGui::PopTextWrapPos();
    return;
  }
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
  row("m", number("%.5g", o.m), tr("Its mass. Its spring to the centre of mass is k = J M m."));
  row("|r \u2212 R|", number("%.5g", o.distance), tr("Distance from the centre of mass R."));
  row(tr("speed"),
      sentence(tr("%s  (%s about R)"), number("%.5g", o.speed), number("%.5g", o.speed_cm)),
      tr("|v| in the lab, and |v \u2212 V| relative to the moving centre of mass."));
  row(tr("energy"),
      number("%.6g", o.energy) + " = " + number("%.4g", o.kinetic_cm) + " + " +
          number("%.4g", o.spring),
      tr("Its own energy: \u00bd m |v \u2212 V|\u00b2 (kinetic, centre-of-mass frame) + "
         "\u00bd J M m |r \u2212 R|\u00b2 (its spring, its share of the potential energy, eq. "
         "13). Constant between wall hits; the particles' energies and the centre of mass's "
         "\u00bd M V\u00b2 add up to E."));
  if (o.period) {
    row(tr("period"), number("%.5g", *o.period),
        tr("2\u03c0/\u221a(J M) from the analytic solution: the same for every particle."));
    row(tr("semi-axes"),
        sentence(tr("%s, %s"), number("%.4g", *o.semi_major), number("%.4g", *o.semi_minor)),
        tr("The ellipse it is on now (eq. 7 from its present position and velocity about the "
           "centre of mass): its largest and smallest distance from R. A wall hit puts it on "
           "another."));
  } else {
    row(tr("period"), tr("none"),
        tr("J \u2264 0: the motion about the centre of mass is free flight or a runaway, with no "
           "period or amplitude."));
  }
  ImGui::EndTable();
  ImGui::PopTextWrapPos();
}

}  // namespace swarmlab
