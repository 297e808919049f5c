#pragma once
// The temporary files an output is being written to, removed if the process is interrupted:
// SIGINT (Ctrl-C) or SIGTERM unlinks every registered path, then the signal takes its usual
// course (the previous handler, or the conventional exit with status 128 + the signal).

#include <string>

namespace swarmlab {

/// Registers path for removal on SIGINT or SIGTERM; installs the handler where it is missing
/// (a signal the process ignores stays ignored).
/// Returns false when the registry is full or the path too long (the caller then refuses to
/// write rather than risk a leftover).
bool register_temp_file(const std::string& path);

/// Forgets path: it was renamed into place or removed.
void unregister_temp_file(const std::string& path);

}  // namespace swarmlab
