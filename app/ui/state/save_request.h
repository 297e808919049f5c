#pragma once
// What the window is saving and asking: one file to save, and the save and quit dialogs'
// state that the app's state holds (save_dialog.h shows the dialogs and writes the file).

#include <optional>
#include <string>

namespace swarmlab {

/// One file to save.
struct SaveRequest {
  std::string what;       ///< for the dialog's title, e.g. "the samples as CSV"
  std::string file_name;  ///< proposed, e.g. "four-masses-samples.csv"
  std::string content;    ///< the bytes; for a preset written at save time under its new name
  const char* mime = "text/plain";
  bool preset = false;  ///< the running preset: the dialog also asks for its name
};

/// The dialogs' state, in AppState.
struct SaveDialog {
  std::optional<SaveRequest> request;  ///< shown in the save dialog while set
  std::string folder;                  ///< the last folder used (the store's default at first)
  std::string file_name, preset_name, error;
  bool open_popup = false;      ///< open the save dialog on the next frame
  bool asking_quit = false;     ///< the quit dialog is up
  bool quit_after_save = false; ///< Save in the quit dialog: quit once the preset is saved
  bool quit_confirmed = false;  ///< the window may close
};

}  // namespace swarmlab
