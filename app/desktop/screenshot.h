#pragma once
// Saving what the window shows as a PNG (desktop only: the browser test takes its own).

#include <string>

namespace swarmlab {

/// Reads the framebuffer being drawn (call before presenting it) and writes it to path as
/// PNG, whole or not at all. Returns an error message, empty on success.
std::string save_screenshot(const std::string& path, int width, int height);

}  // namespace swarmlab
