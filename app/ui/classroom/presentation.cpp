#include "ui/classroom/presentation.h"

#include <imgui.h>

#include <algorithm>

#include "i18n/translator.h"
#include "ui/kit/theme_style.h"
#include "ui/parallel_dom/item_tooltip.h"

namespace swarmlab {

void set_presentation(AppState& state, bool on) {
  Presentation& p = state.presentation;
  Layout& layout = state.layout;
  if (p.on == on) return;
  p.on = on;
  if (on) {
    p.saved_controls = layout.controls;
    p.saved_plots = layout.plots;
    p.saved_ui_scale = layout.pending_ui_scale;
    p.saved_theme = p.theme;
    layout.controls = false;
    layout.plots = true;
    layout.pending_ui_scale = std::max(kPresentationUiScale, layout.pending_ui_scale);
    p.theme = Theme::light;
  } else {
    layout.controls = p.saved_controls;
    layout.plots = p.saved_plots;
    layout.pending_ui_scale = p.saved_ui_scale;
    p.theme = p.saved_theme;
  }
  layout.resize_panels = true;
}

void set_theme(AppState& state, Theme theme) { state.presentation.theme = theme; }

void set_sound(AppState& state, bool on) {
  state.presentation.sound = on;
  if (!on) state.presentation.sound_status.clear();
}

void set_fullscreen(AppState& state, bool on) { state.presentation.fullscreen_wanted = on; }

bool set_page_hidden(AppState& state, bool hidden) {
  Presentation& p = state.presentation;
  if (hidden) {
    if (state.playing && !p.run_while_hidden) {
      state.playing = false;
      p.paused_while_hidden = true;
    }
    return false;
  }
  const bool paused = p.paused_while_hidden;
  p.paused_while_hidden = false;
  return paused;
}

void draw_presentation_menu_items(AppState& state) {
  Presentation& p = state.presentation;
  ImGui::Separator();
  if (ImGui::MenuItem(tr_id("Presentation mode"), "F5", p.on)) set_presentation(state, !p.on);
  if (ImGui::MenuItem(tr_id("Light theme"), nullptr, p.theme == Theme::light))
    set_theme(state, p.theme == Theme::light ? Theme::dark : Theme::light);
  if (ImGui::MenuItem(tr_id("Fullscreen"), "F11", p.fullscreen_wanted))
    set_fullscreen(state, !p.fullscreen_wanted);
  if (ImGui::MenuItem(tr_id("Sound: wall hits"), "M", p.sound)) set_sound(state, !p.sound);
  if (p.can_be_hidden) {
    if (ImGui::MenuItem(tr_id("Keep running in a hidden tab"), nullptr, p.run_while_hidden))
      p.run_while_hidden = !p.run_while_hidden;
    item_tooltip("%s", tr("Off: the run pauses while another tab is in front, sparing the "
                          "battery, and goes on when you press Play."));
  }
}

void draw_sound_toggle(AppState& state) {
  Presentation& p = state.presentation;
  bool on = p.sound;
  if (ImGui::Checkbox(tr_id("Sound"), &on)) set_sound(state, on);
  item_tooltip("%s", tr("M: a click at each wall hit, thinned to a rate you can hear"));
  if (!p.sound_status.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(colour_vec4(palette(state.presentation.theme).text_warning), "%s",
                       p.sound_status.c_str());
  }
}

}  // namespace swarmlab
