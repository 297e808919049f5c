#include <cstdlib>
#include <filesystem>

#include "files/atomic_file.h"
#include "files/config_folder.h"
#include "files/text_file.h"
#include "i18n/language.h"
#include "ui/platform/language_memory.h"

namespace swarmlab {
namespace {

std::string remembered_language() {
  const std::string folder = config_folder();
  if (folder.empty()) return {};
  std::string error;
  std::string code = read_text_file(folder + "/language", error);
  while (!code.empty() && (code.back() == '\n' || code.back() == ' ')) code.pop_back();
  return error.empty() && find_language(code) ? code : std::string();
}

}  // namespace

void remember_language(const std::string& code) {
  const std::string folder = config_folder();
  if (folder.empty()) return;
  std::error_code ignored;
  std::filesystem::create_directories(folder, ignored);
  write_file_atomically(folder + "/language", code + "\n");
}

std::string startup_language() {
  if (std::string code = remembered_language(); !code.empty()) return code;
  // The order POSIX gives them: the first one set decides.
  for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"})
    if (const char* value = std::getenv(name); value && *value) return language_for_locale(value);
  return source_language().code;
}

}  // namespace swarmlab
