#pragma once
// Text inside a PNG file: iTXt chunks (PNG 1.2, section 11.3.4.5; UTF-8, uncompressed), the
// PNG's counterpart of an SVG's <metadata>, so that a PNG figure says what made it
// (provenance.h). Image viewers ignore them; `exiftool`, Pillow's Image.info and
// `identify -verbose` show them.

#include <string>
#include <utility>
#include <vector>

namespace swarmlab::report {

/// png with one iTXt chunk per (keyword, text) inserted after its IHDR chunk; keywords are 1-79
/// Latin-1 characters without NUL ("Software", "Comment"). A text that is not a PNG, or whose
/// first chunk is not IHDR, comes back unchanged.
std::string png_with_text(const std::string& png,
                          const std::vector<std::pair<std::string, std::string>>& entries);

/// The provenance lines (provenance_lines) as a PNG's text: "Software" the first line, and
/// "Comment" all of them, one per line.
std::vector<std::pair<std::string, std::string>> png_text_of(const std::vector<std::string>& lines);

}  // namespace swarmlab::report
