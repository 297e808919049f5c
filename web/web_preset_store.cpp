#include "web_preset_store.h"

#include <emscripten.h>

#include "i18n/translator.h"

namespace swarmlab {
namespace {

// A Blob behind an <a download>: the browser saves it in its downloads folder (or asks where).
// Any bytes (a preset, CSV, SVG, a PNG's binary), copied out of the wasm heap.
// clang-format off
EM_JS(void, start_download_bytes, (const char* name, const void* data, int size, const char* mime), {
  var blob = new Blob([HEAPU8.slice(data, data + size)], {type : UTF8ToString(mime)});
  var a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = UTF8ToString(name);
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(function() { URL.revokeObjectURL(a.href); }, 60000);
});
// clang-format on

class WebPresetStore final : public PresetStore {
 public:
  explicit WebPresetStore(std::string directory)
      : files_(make_file_preset_store(std::move(directory))) {}

  std::vector<ShippedPreset> shipped() override { return files_->shipped(); }

  // Only paths in the in-memory file system (the embedded /presets): the page has no other.
  swarm::PresetParse open(const std::string& location) override { return files_->open(location); }

  std::string save(const std::string& location, const std::string& json) override {
    const std::string text = json + "\n";
    start_download_bytes(download_file_name(location).c_str(), text.data(), int(text.size()),
                         "application/json");
    return {};
  }

  const char* location_hint() const override { return tr("file name for Download preset"); }

  std::string export_file(const std::string& location, const std::string& bytes,
                          const char* mime) override {
    const std::string name = location.substr(location.find_last_of("/\\") + 1);
    start_download_bytes(name.c_str(), bytes.data(), int(bytes.size()), mime);
    return {};
  }

  std::string default_folder() const override { return {}; }  // the browser's downloads

 private:
  std::unique_ptr<PresetStore> files_;
};

}  // namespace

std::string download_file_name(const std::string& location) {
  std::string name = location.substr(location.find_last_of("/\\") + 1);
  if (name.empty()) name = "preset";
  if (name.size() < 5 || name.compare(name.size() - 5, 5, ".json") != 0) name += ".json";
  return name;
}

std::unique_ptr<PresetStore> make_web_preset_store(std::string shipped_directory) {
  return std::make_unique<WebPresetStore>(std::move(shipped_directory));
}

}  // namespace swarmlab
