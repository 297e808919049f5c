#pragma once
// The desktop window of swarmlab: Dear ImGui over SDL2 and OpenGL 3.3.

#include <string>

namespace swarmlab {

struct DesktopOptions {
  std::string preset_path;      ///< preset to open; empty: the first shipped preset
  int frames;                   ///< run this many frames, then exit; 0: until the window closes
  std::string screenshot_path;  ///< after the last frame, save the window as PNG; empty: none
  int select = 0;  ///< select this particle (numbered from 1, as in the table) at the start; 0: none
  bool presentation = false;    ///< start in presentation mode (light theme, large, one plot)
  int plot_tab = 0;  ///< open this plot tab (numbered from 1, left to right) at the start; 0: the preset's
  bool sound = false;  ///< start with the wall clicks on
  bool lesson_summary = false;  ///< with a lesson file: open its summary, as after Finish
  /// After every frame, write its number and its items here as JSON (the parallel DOM's
  /// items_json: role, name, rectangle), so a test finds what to press by role and name.
  std::string items_path;
  /// The language to speak (a code of app/i18n/language.h); empty: the one remembered, else
  /// the system's, English in scripted runs (frames > 0).
  std::string language;
  int threads = 0;  ///< engine threads for the runs; 0: the default (swarm::default_threads)
};

/// Opens the window and runs until it is closed (or for options.frames frames).
/// Returns the process exit code.
int run_desktop(const DesktopOptions& options);

}  // namespace swarmlab
