#pragma once
// The one App of the page, for the code that reaches it from JavaScript (js_api.cpp) and from
// the scenario panel's browser buttons (storage_controls.cpp). web_main.cpp owns it.

#include <memory>
#include <string>

#include "ui/app.h"

namespace swarmlab {

/// The running app, or null before main() has made it.
App* web_app();

/// Opens a preset given as JSON text from `source` ("share link", a file name, "swarmlab.load()").
/// A preset that fails validation leaves the running one alone; the message, as the CLI words
/// it with the source in place of the file name, is shown in the scenario panel and returned.
/// `location` becomes the Download preset file name. Returns an empty string on success.
std::string open_preset_json(AppState& state, const std::string& json, const std::string& source,
                             const std::string& location);

/// The student's lesson progress in the page's localStorage (web_progress_store.cpp).
std::unique_ptr<ProgressStore> make_web_progress_store();

/// Gives the lesson panel its Share button (the page's address + the lesson's fragment, copied
/// and shown) and Load progress... its file picker (js_lessons.cpp).
void install_lesson_share(AppState& state);

/// Starts a browser download of the running preset (the same JSON a desktop Save writes) and
/// says so in the scenario panel. Returns the file name.
std::string download_preset(AppState& state);

}  // namespace swarmlab
