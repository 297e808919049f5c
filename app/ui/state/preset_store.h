#pragma once
// Where presets come from and where they go: the one place the front end touches storage.
// The desktop implementation reads and writes files; the browser build implements the same
// interface over its preloaded files, uploads and downloads.

#include <memory>
#include <string>
#include <vector>

#include "swarm/preset/preset.h"

namespace swarmlab {

/// A preset that ships with the app, for the scenario list.
struct ShippedPreset {
  std::string id;  ///< file name, e.g. "fig1-four-masses.json"
  swarm::Preset preset;
};

class PresetStore {
 public:
  virtual ~PresetStore() = default;

  /// The shipped presets that are valid, in a stable order.
  virtual std::vector<ShippedPreset> shipped() = 0;
  /// Reads and validates a preset; the error names the source and the field.
  virtual swarm::PresetParse open(const std::string& location) = 0;
  /// Stores the preset's JSON; returns an error message, empty on success.
  virtual std::string save(const std::string& location, const std::string& json) = 0;
  /// What the open/save field should say, e.g. "path" on the desktop.
  virtual const char* location_hint() const = 0;
  /// Writes a file the user saves or exports (a preset, CSV, SVG, PNG): on the desktop to the
  /// path given, its folder made if missing, whole or not at all; in the browser as a download
  /// named after the path's last part. Returns an error message, empty on success.
  virtual std::string export_file(const std::string& location, const std::string& bytes,
                                  const char* mime) = 0;
  /// The folder the save dialog starts in; empty where the browser downloads instead.
  virtual std::string default_folder() const = 0;
};

/// Files on disk: shipped presets from `shipped_directory`, saving atomically.
std::unique_ptr<PresetStore> make_file_preset_store(std::string shipped_directory);

}  // namespace swarmlab
