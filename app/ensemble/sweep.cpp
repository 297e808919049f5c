#include "ensemble/sweep.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "ensemble/ensemble_plan.h"
#include "files/text_file.h"
#include "swarm/preset/strict_json.h"
#include "swarm/preset/printable_text.h"

namespace swarmlab::ensemble {
namespace {

using json = nlohmann::json;

/// Limits a grid to what a manifest can hold.
constexpr std::size_t kMaxPoints = 10000;

/// Sets the value at a dotted path of the base preset; "" or why not.
std::string set_key(json& preset, const std::string& key, const json& value) {
  json* at = &preset;
  std::size_t from = 0;
  for (;;) {
    const std::size_t dot = key.find('.', from);
    const std::string part = key.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
    if (!at->is_object() || !at->contains(part))
      return key + ": not a key of the base preset (a sweep varies what the preset already sets)";
    at = &(*at)[part];
    if (dot == std::string::npos) break;
    from = dot + 1;
  }
  *at = value;
  return {};
}

/// "" or a message naming the first key or text value of a point that holds a control
/// character: a point's values go into plan.json, runs.csv and the terminal's table.
std::string control_character_error(const json& values) {
  for (const auto& [key, v] : values.items()) {
    if (const std::string bad = control_character_in(key); !bad.empty())
      return "\"" + swarm::printable(key) + "\": a key that holds " + bad;
    if (v.is_string())
      if (const std::string bad = control_character_in(v.get<std::string>()); !bad.empty())
        return swarm::printable(key) + ": a value that holds " + bad;
  }
  return {};
}

}  // namespace

bool is_sweep(const std::string& text) {
  const json j = json::parse(text, nullptr, false);
  return j.is_object() && j.contains("preset") && (j.contains("grid") || j.contains("points"));
}

SweepRead read_sweep(const std::string& text, const std::string& sweep_path) {
  SweepRead out;
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    out.error = "sweep: not valid JSON at " + swarm::json_syntax_error(e, text);
    return out;
  } catch (const json::exception& e) {
    out.error = "sweep: " + swarm::json_error_text(e);
    return out;
  }
  if (!j.is_object()) {
    out.error = "sweep: must be a JSON object ({\"preset\": ..., \"grid\" or \"points\": ...})";
    return out;
  }
  for (const auto& [key, v] : j.items())
    if (key != "preset" && key != "grid" && key != "points" && key != "seeds") {
      out.error = key + ": unknown key (a sweep has preset, grid or points, and seeds)";
      return out;
    }
  if (!j["preset"].is_string()) {
    out.error = "preset: must be the base preset's file name";
    return out;
  }
  if (const std::string bad = control_character_in(j["preset"].get<std::string>()); !bad.empty()) {
    out.error = "preset: the base preset's file name holds " + bad;
    return out;
  }
  if (j.contains("grid") == j.contains("points")) {
    out.error = "grid, points: give one of them";
    return out;
  }
  Sweep sweep;
  if (j.contains("seeds")) {
    if (!j["seeds"].is_number_integer() || j["seeds"].get<long>() < 1 ||
        j["seeds"].get<long>() > 1000000) {
      out.error = "seeds: must be a whole number from 1 to 1,000,000";
      return out;
    }
    sweep.seeds = j["seeds"].get<long>();
  }
  std::vector<json> points;
  if (j.contains("grid")) {
    const json& grid = j["grid"];
    if (!grid.is_object() || grid.empty()) {
      out.error = "grid: must be an object of keys, each with a list of values";
      return out;
    }
    points.push_back(json::object());
    for (const auto& [key, values] : grid.items()) {
      if (!values.is_array() || values.empty()) {
        out.error = "grid." + key + ": must be a non-empty list of values";
        return out;
      }
      if (points.size() * values.size() > kMaxPoints) {
        out.error = "grid: more than " + std::to_string(kMaxPoints) + " points";
        return out;
      }
      std::vector<json> next;
      for (const json& p : points)
        for (const json& v : values) {
          json q = p;
          q[key] = v;
          next.push_back(q);
        }
      points = std::move(next);
    }
  } else {
    const json& list = j["points"];
    if (!list.is_array() || list.empty() || list.size() > kMaxPoints) {
      out.error = "points: must be a list of 1 to " + std::to_string(kMaxPoints) + " objects";
      return out;
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!list[i].is_object() || list[i].empty()) {
        out.error = "points[" + std::to_string(i) + "]: must be an object of keys and values";
        return out;
      }
      points.push_back(list[i]);
    }
  }

  namespace fs = std::filesystem;
  const std::string base_path =
      (fs::path(sweep_path).parent_path() / j["preset"].get<std::string>()).string();
  std::string unreadable;
  const std::string base_text = read_text_file(base_path, unreadable);
  if (!unreadable.empty()) {
    out.error = "preset: " + unreadable;
    return out;
  }
  const json base = json::parse(base_text, nullptr, false);
  if (base.is_discarded() || !base.is_object()) {
    out.error = "preset: " + base_path + ": not valid JSON";
    return out;
  }
  for (const json& values : points) {
    if (const std::string bad = control_character_error(values); !bad.empty()) {
      out.error = bad;
      return out;
    }
    json preset = base;
    for (const auto& [key, v] : values.items())
      if (std::string err = set_key(preset, key, v); !err.empty()) {
        out.error = err;
        return out;
      }
    const swarm::PresetParse parsed = swarm::parse_preset(preset.dump());
    if (!parsed.preset) {
      out.error = "point " + values.dump() + ": " + parsed.error;
      return out;
    }
    sweep.points.push_back({values.dump(), *parsed.preset});
  }
  out.sweep = std::move(sweep);
  return out;
}

}  // namespace swarmlab::ensemble
