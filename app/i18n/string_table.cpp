#include "i18n/string_table.h"

#include <nlohmann/json.hpp>

namespace swarmlab {

StringTable StringTable::parse(std::string_view json, std::string& error) {
  StringTable table;
  error.clear();
  const nlohmann::json j = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    error = "not valid JSON";
    return table;
  }
  if (!j.is_object()) {
    error = "must be a JSON object of English texts to their translations";
    return table;
  }
  for (const auto& [english, shown] : j.items()) {
    if (!shown.is_string()) {
      error = "\"" + english + "\": the translation must be a string";
      return {};
    }
    const std::string& text = shown.get_ref<const std::string&>();
    if (!text.empty()) table.strings_.emplace(english, text);
  }
  return table;
}

const std::string* StringTable::find(std::string_view english) const {
  const auto it = strings_.find(std::string(english));
  return it == strings_.end() ? nullptr : &it->second;
}

}  // namespace swarmlab
