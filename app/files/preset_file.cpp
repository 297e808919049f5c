#include "files/preset_file.h"

#include <fstream>
#include <sstream>

namespace swarmlab {

swarm::PresetParse read_preset_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  swarm::PresetParse out;
  if (!in) {
    out.error = path + ": cannot open the file";
    return out;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    out.error = path + ": cannot read the file";
    return out;
  }
  out = swarm::parse_preset(text.str());
  if (!out.preset) out.error = path + ": " + out.error;
  return out;
}

}  // namespace swarmlab
