#pragma once
// The browser's PresetStore: the shipped presets come from the /presets folder embedded in
// swarmlab.js (assets/presets), and saving a preset hands it to the browser as a download.
// Opening a file of the user's own is asynchronous in a browser (a file picker), so it does
// not go through open(): see storage_controls.cpp and web/swarmlab_api.js.

#include <memory>
#include <string>

#include "ui/state/preset_store.h"

namespace swarmlab {

/// Shipped presets from `shipped_directory` in Emscripten's in-memory file system; save()
/// starts a download named after the last part of the location.
std::unique_ptr<PresetStore> make_web_preset_store(std::string shipped_directory);

/// A download file name from a location: its last path component, ending in ".json".
std::string download_file_name(const std::string& location);

}  // namespace swarmlab
