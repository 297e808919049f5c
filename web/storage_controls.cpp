#include "storage_controls.h"

#include <emscripten.h>
#include <imgui.h>

#include <cstdio>
#include <map>

#include "i18n/translator.h"
#include "ui/panels/panels.h"
#include "web_app.h"
#include "web_preset_store.h"

namespace swarmlab {
namespace {

// Both run a few milliseconds after the click that pressed the button (ImGui sees the click in
// the next animation frame), well within the browser's transient user activation, which a
// file picker and the clipboard require.
EM_JS(void, js_open_file, (), { Module.swarmlab.openFile(); });
EM_JS(void, js_copy_link, (), { Module.swarmlab.copyLink(); });

std::map<std::string, std::string> button_rects;  // by label, as last drawn
int rects_frame = -1;                             // ImGui's frame count then

/// A button that remembers where it was drawn, under its English label (tests ask by it).
bool button(const char* label, const char* shown) {
  const bool pressed = ImGui::Button(shown);
  const ImVec2 lo = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
  char rect[64];
  std::snprintf(rect, sizeof rect, "%.0f %.0f %.0f %.0f", lo.x, lo.y, size.x, size.y);
  button_rects[label] = rect;
  return pressed;
}

/// Puts the next button on the same line when it fits.
void same_line_if_fits(const char* next_label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(next_label, nullptr, true).x + 2 * style.FramePadding.x;
  const float right = ImGui::GetItemRectMax().x + style.ItemSpacing.x + width;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

}  // namespace

void draw_storage_controls(AppState& state) {
  button_rects.clear();
  rects_frame = ImGui::GetFrameCount();
  if (button("Open preset\u2026", tr_id("Open preset\u2026"))) js_open_file();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", tr("A preset file from this computer (also: drop a .json file on the page)"));
  same_line_if_fits(tr_id("Download preset"));
  if (button("Download preset", tr_id("Download preset"))) download_preset(state);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(tr("The running preset, every edit included, as %s"),
                      download_file_name(state.location).c_str());
  same_line_if_fits(tr_id("Copy link"));
  if (button("Copy link", tr_id("Copy link"))) js_copy_link();
  help_marker(tr(
      "Open preset reads a preset file; Download preset saves the running preset (every edit "
      "you made) as a file that the desktop app, 'swarmlab run' and this page run identically. "
      "Copy link puts the running preset into the page's address (#z=... or #preset=...): "
      "whoever opens that link starts this preset."));
}

std::string storage_button_rect(const std::string& label) {
  // Rects older than the last frame are of a panel that is closed now.
  const auto found = button_rects.find(label);
  if (found == button_rects.end() || rects_frame < ImGui::GetFrameCount() - 1) return {};
  return found->second;
}

}  // namespace swarmlab
