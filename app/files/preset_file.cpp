#include "files/preset_file.h"

#include "files/text_file.h"

namespace swarmlab {

swarm::PresetParse read_preset_file(const std::string& path) {
  swarm::PresetParse out;
  const std::string text = read_text_file(path, out.error);
  if (!out.error.empty()) return out;
  out = swarm::parse_preset(text);
  if (!out.preset) out.error = path + ": " + out.error;
  return out;
}

}  // namespace swarmlab
