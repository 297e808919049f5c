#pragma once
// Reading a preset from disk: the file's errors and the preset's errors in one message.

#include <string>

#include "swarm/preset/preset.h"

namespace swarmlab {

/// Reads and validates a preset file. On failure the message names the file and the field.
swarm::PresetParse read_preset_file(const std::string& path);

}  // namespace swarmlab
