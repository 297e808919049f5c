#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "files/atomic_file.h"
#include "files/preset_file.h"
#include "i18n/translator.h"
#include "ui/state/preset_store.h"

namespace swarmlab {
namespace {

class FilePresetStore final : public PresetStore {
 public:
  explicit FilePresetStore(std::string directory) : directory_(std::move(directory)) {}

  std::vector<ShippedPreset> shipped() override {
    std::vector<ShippedPreset> out;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory_, error)) {
      if (entry.path().extension() != ".json") continue;
      // A shipped preset that fails validation is left out of the list rather than shown
      // broken; the CLI test suite catches it.
      swarm::PresetParse parsed = read_preset_file(entry.path().string());
      if (parsed.preset) out.push_back({entry.path().filename().string(), *parsed.preset});
    }
    std::sort(out.begin(), out.end(),
              [](const ShippedPreset& a, const ShippedPreset& b) { return a.id < b.id; });
    return out;
  }

  swarm::PresetParse open(const std::string& location) override {
    return read_preset_file(location);
  }

  std::string save(const std::string& location, const std::string& json) override {
    if (location.empty()) return tr("give a file name to save to");
    return write_file_atomically(location, json + "\n");
  }

  const char* location_hint() const override { return "path/to/preset.json"; }

  std::string export_file(const std::string& location, const std::string& bytes,
                          const char*) override {
    const std::filesystem::path folder = std::filesystem::path(location).parent_path();
    std::error_code error;
    if (!folder.empty()) std::filesystem::create_directories(folder, error);
    if (error) {
      char text[1200];
      std::snprintf(text, sizeof text, tr("%s: cannot make the folder (%s)"),
                    folder.string().c_str(), error.message().c_str());
      return text;
    }
    return write_file_atomically(location, bytes);
  }

  // Not the working directory, which is wherever the app happened to be started from.
  std::string default_folder() const override {
    const char* home = std::getenv("HOME");
    if (!home || !*home) return std::filesystem::current_path().string();
    return (std::filesystem::path(home) / "Documents" / "Swarm Lab").string();
  }

 private:
  std::string directory_;
};

}  // namespace

std::unique_ptr<PresetStore> make_file_preset_store(std::string shipped_directory) {
  return std::make_unique<FilePresetStore>(std::move(shipped_directory));
}

}  // namespace swarmlab
