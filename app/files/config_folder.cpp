#include "files/config_folder.h"

#include <cstdlib>

namespace swarmlab {

std::string config_folder() {
  const char* config = std::getenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if (config && *config) return std::string(config) + "/swarmlab";
  if (home && *home) return std::string(home) + "/.config/swarmlab";
  return {};
}

}  // namespace swarmlab
