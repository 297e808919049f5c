// Writing a preset as JSON: every key that parse_preset reads, so that text written here reads
// back to the same preset.

#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "swarm/preset/preset.h"

namespace swarm {
namespace {

using json = nlohmann::json;

json to_json(const Preset& p) {
  json j;
  j["version"] = kPresetVersion;
  if (!p.name.empty()) j["name"] = p.name;
  if (!p.description.empty()) j["description"] = p.description;
  j["J"] = p.J;
  if (const auto* list = std::get_if<std::vector<Particle>>(&p.particles)) {
    json arr = json::array();
    for (const auto& q : *list)
      arr.push_back(
          {{"m", q.m}, {"r", {q.r.x(), q.r.y(), q.r.z()}}, {"v", {q.v.x(), q.v.y(), q.v.z()}}});
    j["particles"] = arr;
  } else {
    const auto& s = std::get<SwarmSpec>(p.particles);
    json g;
    g["count"] = s.count;
    if (s.mass_min == s.mass_max)
      g["mass"] = s.mass_min;
    else
      g["mass"] = {{"min", s.mass_min}, {"max", s.mass_max}};
    g["position_radius"] = s.position_radius;
    if (s.velocities == SwarmSpec::Velocities::ball)
      g["velocity"] = {{"speed", s.speed}};
    else
      g["velocity"] = {{"temperature", s.temperature}};
    g["cm_at_rest"] = s.cm_at_rest;
    g["seed"] = s.seed;
    j["particles"] = g;
  }
  j["container"] = p.container_radius ? json{{"radius", *p.container_radius}} : json(nullptr);
  if (p.container_radius && !p.wall_moves.empty()) {
    json moves = json::array();
    for (const WallMove& m : p.wall_moves) moves.push_back({{"to", m.to}, {"speed", m.speed}});
    j["container"]["moves"] = moves;
  }
  if (p.container_radius && p.wall_temperature)
    j["container"]["wall_temperature"] = *p.wall_temperature;
  if (p.sphere_radius) j["hard_spheres"] = {{"radius", *p.sphere_radius}};
  j["method"] = std::string(name_of(p.method));
  j["collisions"] = std::string(name_of(p.collisions));
  j["dt"] = p.dt;
  if (p.expansion) {
    j["expansion"] = {{"factor", p.expansion->factor},
                      {"stages", p.expansion->stages},
                      {"tau", p.expansion->tau},
                      {"thermalize", p.expansion->thermalize_fraction}};
  } else {
    j["duration"] = p.duration;
  }
  if (p.sample_every) j["sample_every"] = *p.sample_every;
  if (!p.compare.empty()) {
    json list = json::array();
    for (Method m : p.compare) list.push_back(std::string(name_of(m)));
    j["compare"] = list;
  }
  if (p.gravity) j["gravity"] = {p.gravity->x(), p.gravity->y(), p.gravity->z()};
  if (p.floor) j["floor"] = {{"z", p.floor->z}, {"restitution", p.floor->restitution}};
  if (p.drag) {
    if (p.drag->mass_proportional())
      j["drag"] = {{"gamma", p.drag->gamma}};
    else
      j["drag"] = {{"b", p.drag->b}, {"particles", p.drag->particles}};
  }
  return j;
}

}  // namespace

std::string preset_to_json(const Preset& p, int indent) { return to_json(p).dump(indent); }

}  // namespace swarm
