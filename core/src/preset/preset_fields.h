#pragma once
// What reading a preset and checking its rules share: every refusal is one message naming the
// field and the rule it breaks, thrown as Invalid and caught once in parse_preset.

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "swarm/preset/preset.h"

namespace swarm::preset_detail {

using json = nlohmann::json;

struct Invalid {
  std::string message;
};

[[noreturn]] void fail(const std::string& field, const std::string& rule);
/// Its message is built whether or not the rule holds: in a loop over the particles, where a
/// preset may list millions, write `if (!ok) fail(...)` instead.
void require(bool ok, const std::string& field, const std::string& rule);

/// A number as the messages print it (ostream's default, 6 significant digits).
std::string format(double x);

/// Reads one JSON object and refuses keys it does not know.
class Fields {
 public:
  Fields(const json& j, std::string path, std::initializer_list<const char*> allowed);

  bool has(const char* key) const { return j_.contains(key) && !j_.at(key).is_null(); }
  const json& at(const char* key) const { return j_.at(key); }
  std::string path(const char* key) const;

  double number(const char* key) const;
  double number(const char* key, double fallback) const;
  std::int64_t integer(const char* key, std::int64_t lo, std::int64_t hi) const;
  std::string text(const char* key, const std::string& fallback) const;
  bool flag(const char* key, bool fallback) const;

  static double number_value(const json& v, const std::string& path);

 private:
  const json& j_;
  std::string path_;
};

/// The rules that look at the particles and the rest of the preset together (preset_rules.cpp);
/// parse_preset applies them once every key is read.
void check_consistency(const Preset& p);

}  // namespace swarm::preset_detail
