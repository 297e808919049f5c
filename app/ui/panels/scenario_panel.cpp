// The scenario panel: the shipped presets with their descriptions, open and save by path,
// reset to the preset as opened.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "files/text_file.h"
#include "i18n/translator.h"
#include "labels/system_labels.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/touch_target.h"
#include "ui/lesson_player/lesson_scene.h"
#include "ui/panels/panels.h"
#include "ui/parallel_dom/item_tooltip.h"
#include "ui/parallel_dom/parallel_dom.h"
#include "ui/platform/save_dialog.h"

namespace swarmlab {

void show_refusal(AppState& state, Section section) {
  if (state.draft_error.empty() || state.draft_error_section != section) return;
  ImGui::PushStyleColor(ImGuiCol_Text, colour_vec4(palette(state.presentation.theme).text_error));
  // The preset rules' message stays English (the CLI's), after a translated sentence.
  ImGui::TextWrapped(tr("Not applied: %s"), state.draft_error.c_str());
  ImGui::PopStyleColor();
  if (ImGui::Button(tr_id("Undo the edit"), ImVec2(target_width(tr_id("Undo the edit")), 0)))
    state.revert_draft();
  item_tooltip("%s", tr("Show the running values again. Until then the run goes on with the "
                        "last valid preset."));
}

void help_marker(const char* text) {
  // On the next line where the row is full, never broken over lines itself ("(", "?", ")").
  same_line_if_fits(ImGui::CalcTextSize("(?)").x);
  mirror_text(ItemRole::paragraph, text);  // a screen reader reads the help where it stands
  ImGui::PushTextWrapPos(-1.0f);
  ImGui::TextDisabled("(?)");
  ImGui::PopTextWrapPos();
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

bool committed() { return ImGui::IsItemDeactivatedAfterEdit(); }

void draw_scenario_panel(AppState& state) {
  ImGui::TextDisabled("%s", tr("Shipped presets"));
  const float list_height = ImGui::GetTextLineHeightWithSpacing() *
                            (float(std::min<std::size_t>(state.shipped.size(), 7)) + 0.4f);
  if (ImGui::BeginListBox("##presets", ImVec2(-1, list_height))) {
    for (const ShippedPreset& s : state.shipped) {
      const bool current = state.shipped_id == s.id;
      // A shipped preset's name and description are keys of the string tables; the ID is the
      // file's, whatever the language.
      const std::string name = s.preset.name.empty() ? s.id : std::string(tr(s.preset.name.c_str()));
      const std::string label = name + "###" + s.id;
      // A name longer than the list is wide (a translation's) wraps onto a second line.
      const float room = ImGui::GetContentRegionAvail().x;
      const ImVec2 text_size = ImGui::CalcTextSize(name.c_str(), nullptr, false, room);
      bool picked = false;
      if (ImGui::CalcTextSize(name.c_str()).x <= room) {
        picked = ImGui::Selectable(label.c_str(), current);
      } else {
        const ImVec2 at = ImGui::GetCursorScreenPos();  // where a selectable puts its text
        picked = ImGui::Selectable(("###" + s.id).c_str(), current, 0, ImVec2(0, text_size.y));
        name_item(name);
        ImGui::GetWindowDrawList()->AddText(nullptr, 0, at,
                                            ImGui::GetColorU32(ImGuiCol_Text), name.c_str(),
                                            nullptr, room);
      }
      if (picked) {
        // Saving goes to a copy in the working directory, never over the shipped file.
        state.open(s.preset, "my-" + s.id);
        state.shipped_id = s.id;
      }
      if (ImGui::IsItemHovered() && !s.preset.description.empty()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 26);
        ImGui::TextUnformatted(tr(s.preset.description.c_str()));
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
    }
    ImGui::EndListBox();
  }

  ImGui::Spacing();
  ImGui::PushStyleColor(ImGuiCol_Text, colour_vec4(palette(state.presentation.theme).text_key));
  ImGui::TextWrapped("%s", labels::title(state.preset, state.modified).c_str());
  ImGui::PopStyleColor();
  // The description was written for the preset as shipped; after an edit it may no longer hold.
  if (state.modified && !state.preset.description.empty())
    ImGui::TextDisabled("%s", tr("As shipped (before the edits):"));
  if (!state.preset.description.empty()) {
    // ImGui wraps the whole text every frame: a description of a million characters (from a
    // link or a file) would take the frame rate down to one a second, so a long one is cut.
    constexpr std::size_t kShown = 2000;  // bytes of UTF-8
    // A shipped description is a key of the string tables (and short); a long one from a link
    // is shown as written, not looked up every frame.
    const std::string& written = state.preset.description;
    const std::string translated = written.size() <= kShown ? tr(written.c_str()) : std::string();
    const std::string& text = written.size() <= kShown ? translated : written;
    std::size_t end = std::min(text.size(), kShown);
    while (end < text.size() && end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80)
      --end;  // not inside a character
    const std::string shown = end < text.size() ? text.substr(0, end) + "..." : text;
    ImGui::TextWrapped("%s", shown.c_str());
  }
  if (state.modified && ImGui::Button(tr_id("Reset to preset"))) {
    state.draft = state.origin;
    state.apply_draft(Section::scenario);
  }

  ImGui::Spacing();
  if (state.storage_controls) {
    state.storage_controls(state);
  } else {
    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##location", state.store->location_hint(), &state.location);
    if (ImGui::Button(tr_id("Open"))) {
      // A lesson file opens as a lesson, anything else as a preset (as a dropped file does in
      // the browser).
      std::string error;
      const std::string text = read_text_file(state.location, error);
      if (error.empty()) {
        error = open_file_text(state, text, state.location);
        if (!error.empty()) error = state.location + ": " + error;
      }
      if (error.empty()) {
        // One sentence with the location in it, as long as the location needs.
        const char* format = tr("Opened %s");
        const int length = std::snprintf(nullptr, 0, format, state.location.c_str());
        state.status.assign(std::size_t(std::max(length, 0)), '\0');
        std::snprintf(state.status.data(), state.status.size() + 1, format, state.location.c_str());
        state.status_is_error = false;
      } else {
        state.status = error;
        state.status_is_error = true;
      }
    }
    ImGui::SameLine();
    if (ImGui::Button(tr_id("Save..."))) request_save_preset(state);
    help_marker(
        tr("Open reads a preset file; Save asks for a name, folder and file name and writes the "
           "running preset (every edit you made) as a preset file that 'swarmlab run' and the "
           "browser run identically. Files are written whole or not at all."));
  }
  if (ImGui::Button(tr_id("Export samples CSV"))) request_samples_csv(state);
  if (!state.run->primary().stages().empty()) {
    ImGui::SameLine();
    if (ImGui::Button(tr_id("Export stages CSV"))) request_stages_csv(state);
  }
  if (!state.status.empty()) {
    const Palette& colours = palette(state.presentation.theme);
    ImGui::PushStyleColor(ImGuiCol_Text, colour_vec4(state.status_is_error ? colours.text_error
                                                                           : colours.text_ok));
    ImGui::TextWrapped("%s", state.status.c_str());
    ImGui::PopStyleColor();
  }
  show_refusal(state, Section::scenario);
}

}  // namespace swarmlab
