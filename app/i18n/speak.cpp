#include "i18n/speak.h"

#include "i18n/embedded_tables.h"
#include "i18n/translator.h"

namespace swarmlab {

bool speak(std::string_view code, std::string& error) {
  const Language* language = find_language(code);
  if (!language) {
    error = "lang: \"" + std::string(code) + "\" is not a language Swarm Lab speaks";
    return false;
  }
  StringTable table;
  const std::string_view text = embedded_table(language->code);
  if (!text.empty()) {
    table = StringTable::parse(text, error);
    if (!error.empty()) {
      error = "assets/i18n/" + language->code + ".json: " + error;
      return false;
    }
  }
  translator().use(*language, std::move(table));
  error.clear();
  return true;
}

}  // namespace swarmlab
