#pragma once
// A whole file read as text: the one reader behind presets, lessons, sweeps, run records,
// ensemble plans and reports.

#include <string>

namespace swarmlab {

/// The file's bytes; on failure "" and `error` set to "PATH: cannot open the file" (or
/// "... cannot read the file").
std::string read_text_file(const std::string& path, std::string& error);

}  // namespace swarmlab
