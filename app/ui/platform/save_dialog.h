#pragma once
// Saving and exporting from the window: the running preset under a name the user gives, the
// samples and stages as CSV (the CLI's columns, report/run_csv.h), a plot as SVG. On the
// desktop a dialog shows the folder and the file name, both editable, and writes through the
// store (whole or not at all); in the browser the file is a download. And the question asked
// before quitting with unsaved edits.

#include <string>

#include "ui/state/app_state.h"

namespace swarmlab {

/// "Four masses (paper Fig. 1)" -> "four-masses-paper-fig-1": a file name stem from a name.
std::string file_stem_of(const std::string& name);

/// Saves request: in the browser at once (a download), on the desktop after the dialog.
void request_save(AppState& state, SaveRequest request);
/// Save preset... : the running preset with its edits, under the name the user gives.
void request_save_preset(AppState& state);
/// The samples as CSV; returns the file name proposed (the download's name in the browser).
std::string request_samples_csv(AppState& state);
/// The finished stages as CSV; returns the file name proposed.
std::string request_stages_csv(AppState& state);

/// Closing the window or Quit: asks first when the running preset has unsaved edits.
void request_quit(AppState& state);

/// The save and quit dialogs, once per frame (modal ImGui popups).
void draw_save_dialogs(AppState& state);

}  // namespace swarmlab
