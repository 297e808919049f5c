#pragma once
// A whole file read as text: the one reader behind presets, lessons, sweeps, run records,
// ensemble plans and reports. Only a regular file is read, and never more than a limit: a
// FIFO, a device (/dev/zero behind a symlink) or a file grown without end is refused with a
// message instead of a hang or a process that eats the machine's memory.

#include <cstddef>
#include <string>

namespace swarmlab {

/// What the CLI reads by default: presets, lessons, sweeps, plans and run records are all far
/// smaller (a run record is about 20 kB, a 10,000-point plan about 1 MB).
inline constexpr std::size_t kTextFileLimit = std::size_t(16) << 20;

struct TextFile {
  std::string text;
  std::string error;  ///< "" or why not, without the path: "not a regular file (a FIFO)"
  bool missing = false;  ///< there is nothing at the path
};

/// The bytes of the regular file at `path` (a symlink is followed), at most `limit` of them.
/// Checked before it is opened (so a device is never opened) and again on the opened file (so
/// a file swapped in between is caught); opened without blocking, so a FIFO never waits for a
/// writer.
TextFile read_regular_file(const std::string& path, std::size_t limit = kTextFileLimit);

/// The same, on failure "" and `error` set to "PATH: why" ("PATH: cannot open the file",
/// "PATH: not a regular file (a FIFO); only regular files are read", "PATH: larger than 16 MB,
/// the most this file may hold").
std::string read_text_file(const std::string& path, std::string& error,
                           std::size_t limit = kTextFileLimit);

}  // namespace swarmlab
