#include "lessons/lesson_file.h"

#include <algorithm>
#include <filesystem>

#include "files/preset_file.h"
#include "swarm/preset/printable_text.h"
#include "files/text_file.h"

namespace swarmlab {

PresetLookup shipped_preset_lookup(std::string directory) {
  return [directory = std::move(directory)](const std::string& name) {
    swarm::PresetParse out;
    const bool plain = !name.empty() && name.find_first_of("/\\") == std::string::npos &&
                       name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0 &&
                       name.find("..") == std::string::npos;
    if (!plain) {
      out.error = "\"" + swarm::printable(name) +
                  "\" is not a shipped preset's file name (such as \"two-body-circular.json\")";
      return out;
    }
    // Looked up without opening it: a FIFO under that name must not block (read_preset_file
    // refuses anything but a regular file).
    std::error_code ec;
    if (!std::filesystem::exists(directory + "/" + name, ec)) {
      out.error = "no shipped preset \"" + swarm::printable(name) + "\"";
      return out;
    }
    out = read_preset_file(directory + "/" + name);
    return out;
  };
}

LessonParse read_lesson_file(const std::string& path, const PresetLookup& lookup) {
  LessonParse out;
  const std::string text = read_text_file(path, out.error);
  if (!out.error.empty()) return out;
  out = parse_lesson(text, lookup);
  if (!out.lesson) out.error = path + ": " + out.error;
  return out;
}

std::vector<Lesson> load_shipped_lessons(const std::string& directory, const PresetLookup& lookup,
                                         std::string& problems) {
  std::vector<std::string> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  std::vector<Lesson> out;
  for (const std::string& file : files) {
    LessonParse parsed = read_lesson_file(file, lookup);
    if (parsed.lesson)
      out.push_back(std::move(*parsed.lesson));
    else
      problems += "error: " + parsed.error + "\n";
  }
  return out;
}

}  // namespace swarmlab
