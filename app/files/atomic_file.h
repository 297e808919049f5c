#pragma once
// Output files appear whole or not at all: written to a temporary beside the target, then
// renamed over it, so an interrupted run never leaves half a file.

#include <string>

namespace swarmlab {

/// Writes contents to path atomically; on failure returns a message and leaves path untouched.
std::string write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace swarmlab
