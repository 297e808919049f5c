// The rules between keys: what no single key can be refused for alone, checked once every key
// is read (and, through preset_error, on a preset built in code).

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "preset/preset_fields.h"
#include "swarm/preset/preset.h"

namespace swarm {
namespace preset_detail {
namespace {

constexpr long kMaxPairwiseParticles = 20'000;

/// The rules that tie the Appendix B keys to the rest of the preset.
void check_walls_and_contacts(const Preset& p, long count) {
  const bool appendix_b = !p.wall_moves.empty() || p.wall_temperature || p.sphere_radius;
  if (p.collisions == CollisionMode::exact)
    require(!appendix_b, "collisions",
            "\"exact\" solves contact times with a fixed elastic wall only: moving and hot "
            "walls and hard spheres use \"paper\"");
  if (!p.wall_moves.empty())
    require(!p.expansion, "expansion",
            "the wall already moves (container.moves): give moves or an expansion, not both");
  if (!p.sphere_radius) return;
  // The floor's contact test is made for a point: a sphere would sink by its radius into it.
  require(!p.floor, "floor",
          "hard spheres on a floor are not modelled yet (the floor would meet each sphere's "
          "centre, not its surface): give floor or hard_spheres, not both");
  const double a = *p.sphere_radius;
  if (!p.container_radius) return;
  double smallest = *p.container_radius;
  for (std::size_t i = 0; i < p.wall_moves.size(); ++i) {
    require(p.wall_moves[i].to > 2 * a, "container.moves[" + std::to_string(i) + "].to",
            "must be > 2 * hard_spheres.radius (a sphere must fit inside)");
    smallest = std::min(smallest, p.wall_moves[i].to);
  }
  require(*p.container_radius > 2 * a, "hard_spheres.radius",
          "must be < container.radius / 2 (a sphere must fit inside)");
  const double reach = *p.container_radius - a;  // the centres' room
  if (const auto* list = std::get_if<std::vector<Particle>>(&p.particles)) {
    for (std::size_t i = 0; i < list->size(); ++i)
      if (!((*list)[i].r.norm() <= reach))
        fail("particles[" + std::to_string(i) + "].r",
             "a sphere's centre must start within container.radius - hard_spheres.radius = " +
                 format(reach));
  } else {
    require(std::get<SwarmSpec>(p.particles).position_radius <= reach, "particles.position_radius",
            "must be <= container.radius - hard_spheres.radius = " + format(reach) +
                " (the spheres must start inside)");
  }
  // Random starts overlap; beyond about half of the volume the centres can hardly move.
  const double fraction = double(count) * std::pow(a / (smallest - a), 3);
  require(fraction <= 0.5, "hard_spheres.radius",
          "the spheres would fill " + format(fraction) +
              " of the volume their centres can reach (at most 0.5)");
}

/// Gravity, floor and drag against the particles: everyone starts on or above the floor, and
/// drag.particles name particles that exist.
void check_forces_consistency(const Preset& p, long count) {
  if (p.floor) {
    if (const auto* list = std::get_if<std::vector<Particle>>(&p.particles)) {
      for (std::size_t i = 0; i < list->size(); ++i)
        if (!((*list)[i].r.z() >= p.floor->z))
          fail("particles[" + std::to_string(i) + "].r",
               "starts below the floor (z = " + format((*list)[i].r.z()) +
                   " < floor.z = " + format(p.floor->z) + ")");
    } else {
      const auto& s = std::get<SwarmSpec>(p.particles);
      require(p.floor->z <= -s.position_radius, "floor.z",
              "must be <= -particles.position_radius (the swarm is generated in a ball about "
              "the origin and must start above the floor)");
    }
  }
  if (p.drag)
    for (std::size_t i = 0; i < p.drag->particles.size(); ++i)
      if (long(p.drag->particles[i]) >= count)
        fail("drag.particles[" + std::to_string(i) + "]",
             "particle " + std::to_string(p.drag->particles[i]) + " does not exist (there are " +
                 std::to_string(count) + ", numbered from 0)");
}

}  // namespace

void check_consistency(const Preset& p) {
  long count = 0;
  if (const auto* list = std::get_if<std::vector<Particle>>(&p.particles)) {
    count = long(list->size());
    if (p.container_radius) {
      for (std::size_t i = 0; i < list->size(); ++i) {
        const double r = (*list)[i].r.norm();
        if (!(r <= *p.container_radius))
          fail("particles[" + std::to_string(i) + "].r",
               "starts outside the container (|r| = " + format(r) +
                   " > container.radius = " + format(*p.container_radius) + ")");
      }
    }
  } else {
    const auto& s = std::get<SwarmSpec>(p.particles);
    count = s.count;
    if (p.container_radius)
      require(s.position_radius <= *p.container_radius, "particles.position_radius",
              "must be <= container.radius (particles must start inside the container)");
  }
  check_forces_consistency(p, count);
  check_walls_and_contacts(p, count);
  for (Method m : p.compare)
    require(!is_pairwise(m) || count <= kMaxPairwiseParticles, "compare",
            "\"" + std::string(name_of(m)) + "\" sums over every pair: use at most " +
                std::to_string(kMaxPairwiseParticles) + " particles");
  if (is_pairwise(p.method))
    require(count <= kMaxPairwiseParticles, "method",
            "\"" + std::string(name_of(p.method)) + "\" sums over every pair: use at most " +
                std::to_string(kMaxPairwiseParticles) + " particles (got " + std::to_string(count) +
                ")");
}

}  // namespace preset_detail

std::string preset_error(const Preset& p, const ResourceLimits& limits) {
  return parse_preset(preset_to_json(p), limits).error;
}

}  // namespace swarm
