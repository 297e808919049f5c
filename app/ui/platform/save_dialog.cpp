#include "ui/platform/save_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "i18n/translator.h"
#include "report/run_csv.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/touch_target.h"

namespace swarmlab {
namespace {

/// The status line after a file was written: "Saved LOCATION".
std::string saved_status(const std::string& location) {
  char text[600];
  std::snprintf(text, sizeof text, tr("Saved %s"), location.c_str());
  return text;
}

/// A value as the student reads it: "7.5", or "7,5" in a language that writes a comma.
std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return translator().numbers(text);
}

std::string preset_json_named(const AppState& state, const std::string& name) {
  swarm::Preset p = state.preset;
  p.name = name;
  return swarm::preset_to_json(p) + "\n";
}

/// Writes the request where the user said; on success a preset becomes the saved, unedited
/// origin under its new name. Returns the error, empty on success.
std::string write(AppState& state, const SaveRequest& request, const std::string& location,
                  const std::string& preset_name) {
  const std::string content =
      request.preset ? preset_json_named(state, preset_name) : request.content;
  const std::string error = state.store->export_file(location, content, request.mime);
  state.status = error.empty() ? saved_status(location) : error;
  state.status_is_error = !error.empty();
  if (error.empty() && request.preset) {
    state.preset.name = state.draft.name = preset_name;
    state.origin = state.preset;
    state.modified = false;
    state.location = location;
  }
  return error;
}

/// A CSV file named after the running preset; returns the file name proposed.
std::string request_csv(AppState& state, std::string what, const char* suffix,
                        std::string content) {
  const std::string name = file_stem_of(state.preset.name) + suffix;
  request_save(state, {std::move(what), name, std::move(content), "text/csv", false});
  return name;
}

}  // namespace

std::string file_stem_of(const std::string& name) {
  std::string stem;
  for (const unsigned char c : name) {
    if (std::isalnum(c))
      stem += char(std::tolower(c));
    else if (!stem.empty() && stem.back() != '-')
      stem += '-';
  }
  while (!stem.empty() && stem.back() == '-') stem.pop_back();
  return stem.empty() ? "swarm-lab" : stem;
}

void request_save(AppState& state, SaveRequest request) {
  SaveDialog& d = state.save_dialog;
  const std::string folder = state.store->default_folder();
  if (folder.empty()) {  // the browser: a download, named by the app
    write(state, request, request.file_name, state.preset.name);
    return;
  }
  if (d.folder.empty()) d.folder = folder;
  d.file_name = request.file_name;
  d.preset_name = state.preset.name;
  d.error.clear();
  d.request = std::move(request);
  d.open_popup = true;
}

void request_save_preset(AppState& state) {
  SaveRequest r;
  r.what = tr("the running preset (every edit included)");
  r.file_name = file_stem_of(state.preset.name) + ".json";
  r.mime = "application/json";
  r.preset = true;
  request_save(state, std::move(r));
}

std::string request_samples_csv(AppState& state) {
  // The samples are those of the run as it is now: after a seek back they end at the present
  // time, not at the furthest time reached. The file's name and the dialog say which range it
  // holds rather than leave a shorter run to be taken for the whole.
  const double now = state.run->time();
  const double reached = double(state.run->timeline().reached()) * state.preset.dt;
  if (state.run->step() >= state.run->timeline().reached())
    return request_csv(state, tr("the samples as CSV (the columns of swarmlab run --csv)"),
                       "-samples.csv", report::samples_csv(state.run->primary().samples()));
  char what[400], suffix[64];
  std::snprintf(what, sizeof what,
                tr("the samples from t = 0 to t = %.4g, the time shown, as CSV (the run reached "
                   "t = %.4g: play on or press End to export all of it)"),
                now, reached);
  std::snprintf(suffix, sizeof suffix, "-samples-t0-to-t%.4g.csv", now);
  const std::string name =
      request_csv(state, translator().numbers(what), suffix,
                  report::samples_csv(state.run->primary().samples()));
  // Saved at once (the browser's download): the status line says which range the file holds.
  if (!state.status_is_error && state.status == saved_status(name)) {
    char text[700];
    std::snprintf(text, sizeof text, tr("Saved %s (t = 0 to %s of the %s reached)"),
                  name.c_str(), number_text(now).c_str(), number_text(reached).c_str());
    state.status = text;
  }
  return name;
}

std::string request_stages_csv(AppState& state) {
  // The columns from the writer's own header, so that a new column changes one place.
  char what[200];
  std::snprintf(what, sizeof what, tr("the expansion stages as CSV (%s)"), report::kStagesCsvHeader);
  return request_csv(state, what, "-stages.csv", report::stages_csv(state.run->primary().stages()));
}

void request_quit(AppState& state) {
  if (state.modified && !state.store->default_folder().empty())
    state.save_dialog.asking_quit = true;
  else
    state.save_dialog.quit_confirmed = true;
}

void draw_save_dialogs(AppState& state) {
  SaveDialog& d = state.save_dialog;
  const float font = ImGui::GetFontSize();
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();

  if (d.asking_quit) ImGui::OpenPopup(tr_id("Unsaved edits"));
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal(tr_id("Unsaved edits"), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text(tr("\u201c%s\u201d has edits that are not saved."), tr(state.preset.name.c_str()));
    ImGui::TextDisabled("%s", tr("Quit anyway, or save the preset first?"));
    if (ImGui::Button(tr_id("Save..."))) {
      d.asking_quit = false;
      d.quit_after_save = true;
      ImGui::CloseCurrentPopup();
      request_save_preset(state);
    }
    ImGui::SameLine();
    if (ImGui::Button(tr_id("Discard and quit"))) {
      d.asking_quit = false;
      d.quit_confirmed = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button(tr_id("Cancel")) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      d.asking_quit = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  if (d.open_popup) {
    ImGui::OpenPopup(tr_id("Save"));
    d.open_popup = false;
  }
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(34 * font, 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal(tr_id("Save"), nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    if (!d.request) {
      ImGui::CloseCurrentPopup();
    } else {
      ImGui::TextWrapped(tr("Save %s"), d.request->what.c_str());
      ImGui::Spacing();
      // The fields leave room for the longest of their labels (a translation's too).
      float label_room = 8 * font;
      for (const char* label : {tr_id("preset name"), tr_id("folder"), tr_id("file name")})
        label_room = std::max(label_room, ImGui::CalcTextSize(label, nullptr, true).x +
                                              ImGui::GetStyle().ItemInnerSpacing.x);
      if (d.request->preset) {
        ImGui::SetNextItemWidth(-label_room);
        ImGui::InputText(tr_id("preset name"), &d.preset_name);
      }
      ImGui::SetNextItemWidth(-label_room);
      ImGui::InputText(tr_id("folder"), &d.folder);
      ImGui::SetNextItemWidth(-label_room);
      ImGui::InputText(tr_id("file name"), &d.file_name);
      const std::string location = (std::filesystem::path(d.folder) / d.file_name).string();
      ImGui::PushTextWrapPos(0);
      ImGui::TextDisabled("%s", location.c_str());
      ImGui::PopTextWrapPos();
      if (!d.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text,
                              colour_vec4(palette(state.presentation.theme).text_error));
        ImGui::TextWrapped("%s", d.error.c_str());
        ImGui::PopStyleColor();
      }
      const bool can_save = !d.file_name.empty() && !(d.request->preset && d.preset_name.empty());
      ImGui::BeginDisabled(!can_save);
      const bool save = ImGui::Button(tr_id("Save"), ImVec2(std::max(6 * font, target_width(tr_id("Save"))), 0));
      ImGui::EndDisabled();
      same_line_if_fits(target_width(tr_id("Cancel")));
      const bool cancel =
          ImGui::Button(tr_id("Cancel")) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
      if (save) {
        // The folder is made if missing; the file appears whole or not at all.
        d.error = write(state, *d.request, location, d.preset_name);
        if (d.error.empty()) {
          if (d.quit_after_save && d.request->preset) d.quit_confirmed = true;
          d.request.reset();
          ImGui::CloseCurrentPopup();
        }
      } else if (cancel) {
        d.request.reset();
        d.quit_after_save = false;
        ImGui::CloseCurrentPopup();
      }
    }
    ImGui::EndPopup();
  }
}

}  // namespace swarmlab
