#pragma once
// Lessons and the presets they name, read from disk (the CLI, the desktop, the browser's
// embedded files).

#include <string>
#include <vector>

#include "lessons/lesson.h"

namespace swarmlab {

/// Looks a shipped preset's file name up in `directory`. Only a plain file name ending in
/// ".json" is looked up (no folders), so a lesson cannot reach other files.
PresetLookup shipped_preset_lookup(std::string directory);

/// Reads and validates a lesson file. On failure the message names the file and the field.
LessonParse read_lesson_file(const std::string& path, const PresetLookup& lookup);

/// The valid lessons in `directory` (*.json, in file-name order). Each invalid one adds a line
/// "error: FILE: field: rule" to `problems` and is left out, so one broken file does not hide
/// the rest.
std::vector<Lesson> load_shipped_lessons(const std::string& directory, const PresetLookup& lookup,
                                         std::string& problems);

}  // namespace swarmlab
