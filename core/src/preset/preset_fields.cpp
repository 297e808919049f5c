// The one place a preset's messages are shaped: "field: rule", the numbers in them, and the
// keys a JSON object may hold.

#include "preset/preset_fields.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string_view>
#include <utility>

#include "swarm/preset/printable_text.h"

namespace swarm::preset_detail {
namespace {

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

}  // namespace

[[noreturn]] void fail(const std::string& field, const std::string& rule) {
  throw Invalid{field + ": " + rule};
}

void require(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) fail(field, rule);
}

std::string format(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

Fields::Fields(const json& j, std::string path, std::initializer_list<const char*> allowed)
    : j_(j), path_(std::move(path)) {
  if (!j.is_object()) fail(path_.empty() ? "preset" : path_, "must be a JSON object");
  for (const auto& [key, value] : j.items()) {
    if (std::find(allowed.begin(), allowed.end(), std::string_view(key)) != allowed.end()) continue;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail(join(path_, printable(key)), "unknown key (allowed here: " + list + ")");
  }
}

std::string Fields::path(const char* key) const { return join(path_, key); }

double Fields::number(const char* key) const {
  if (!has(key)) fail(path(key), "missing (a number is required)");
  return number(key, 0.0);
}

double Fields::number(const char* key, double fallback) const {
  if (!has(key)) return fallback;
  // The path is built only for a refusal: a list of particles reads millions of numbers.
  const json& v = at(key);
  if (v.is_number() && std::isfinite(v.get<double>())) return v.get<double>();
  return number_value(v, path(key));
}

std::int64_t Fields::integer(const char* key, std::int64_t lo, std::int64_t hi) const {
  if (!has(key)) fail(path(key), "missing (an integer is required)");
  const json& v = at(key);
  if (!v.is_number_integer())
    fail(path(key), v.is_number() ? "must be a whole number" : "must be an integer");
  const long long x = v.is_number_unsigned() ? (long long)std::min<unsigned long long>(
                                                   v.get<unsigned long long>(), 1ull << 62)
                                             : v.get<long long>();
  if (x < lo || x > hi)
    fail(path(key), "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return std::int64_t(x);
}

std::string Fields::text(const char* key, const std::string& fallback) const {
  if (!has(key)) return fallback;
  if (!at(key).is_string()) fail(path(key), "must be a string");
  return at(key).get<std::string>();
}

bool Fields::flag(const char* key, bool fallback) const {
  if (!has(key)) return fallback;
  if (!at(key).is_boolean()) fail(path(key), "must be true or false");
  return at(key).get<bool>();
}

double Fields::number_value(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(path, "must be a finite number");
  return x;
}

}  // namespace swarm::preset_detail
