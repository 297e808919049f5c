#pragma once
// Where the desktop app keeps what it remembers between runs (lesson progress, the language).

#include <string>

namespace swarmlab {

/// $XDG_CONFIG_HOME/swarmlab, else ~/.config/swarmlab; empty when neither is set.
std::string config_folder();

}  // namespace swarmlab
