#include "ui/state/app_state.h"

#include <algorithm>
#include <cmath>

#include "labels/system_labels.h"
#include "swarm/physics/regime.h"

namespace swarmlab {
namespace {

constexpr std::size_t kSmallSystem = 20;  // up to here every particle gets a trail

std::size_t particle_count(const swarm::Preset& p) {
  if (const auto* list = std::get_if<std::vector<swarm::Particle>>(&p.particles))
    return list->size();
  return std::size_t(std::get<swarm::SwarmSpec>(p.particles).count);
}

/// The browser runs on school Chromebooks: a preset beyond their means is refused in the page
/// within a second, before anything is allocated, and the running one carries on.
swarm::ResourceLimits resource_limits_here() {
#ifdef __EMSCRIPTEN__
  return swarm::browser_limits();
#else
  return {};
#endif
}

}  // namespace

void AppState::open(const swarm::Preset& p, std::string from) {
  origin = preset = draft = p;
  location = std::move(from);
  shipped_id.clear();
  draft_error.clear();
  draft_error_section = Section::none;
  modified = false;
  selected.reset();
  restart();

  // Start at a pace a class can follow: a period in five seconds, an expansion stage in ten.
  const swarm::System& s = run->system();
  const double time_scale = swarm::natural_time_of(swarm::stiffness(s));
  if (p.expansion)
    speed = p.expansion->tau / 10;
  else if (std::isfinite(time_scale))
    speed = time_scale / 5;
  else
    speed = p.duration / 20;
  speed = std::clamp(speed, 1e-3, 1e4);

  view.follow_cm = !p.container_radius;
  view.springs = particle_count(p) <= 6 ? SpringOverlay::pairs : SpringOverlay::off;
  plots.tab = !p.compare.empty()    ? PlotTab::compare
              : p.expansion         ? PlotTab::expansion
              : p.container_radius  ? PlotTab::wall
                                    : PlotTab::energy;
  plots.average_window = 20.0 * double(run->primary().plan().sample_every) * p.dt;
  plots.scroll_window = 0;
  reframe = true;
}

std::string AppState::open_json(const std::string& json, std::string from) {
  const swarm::PresetParse parsed = swarm::parse_preset(json, resource_limits_here());
  if (!parsed.preset) {
    status = parsed.error;
    status_is_error = true;
    return parsed.error;
  }
  open(*parsed.preset, std::move(from));
  // A link or a file is not the shipped preset whose name it may carry: it is edited unless it
  // equals one, and Reset returns to the shipped preset of its name when there is one.
  std::vector<swarm::Preset> shipped_presets;
  for (const ShippedPreset& s : shipped) {
    shipped_presets.push_back(s.preset);
    if (s.preset.name == preset.name) origin = s.preset;
  }
  modified = labels::differs_from_shipped(preset, shipped_presets);
  status.clear();
  return {};
}

bool AppState::apply_draft(Section section) {
  const std::string error = swarm::preset_error(draft, resource_limits_here());
  if (!error.empty()) {
    draft_error = error;
    draft_error_section = section;
    return false;
  }
  draft_error.clear();
  draft_error_section = Section::none;
  preset = draft;
  modified = swarm::preset_to_json(preset) != swarm::preset_to_json(origin);
  restart();
  return true;
}

void AppState::revert_draft() {
  draft = preset;
  draft_error.clear();
  draft_error_section = Section::none;
}

void AppState::restart() {
  // A seek under way ends with the run it was in.
  if (travel.kind == TimeTravel::Kind::to_time && run)
    travel_ends.push_back({travel.id, run->time(), false});
  travel = {};
  run = std::make_unique<LiveRun>(preset, engine_threads);
  step_debt = 0;
  colour_scale = ColourScale{};
  const swarm::System& s = run->system();
  if (selected && *selected >= s.particles.size()) selected.reset();

  // The scene: the container, or the swarm's extent about its centre of mass.
  const swarm::Vec3 cm = swarm::cm_position(s);
  double extent = 0, heaviest = 0;
  for (const auto& q : s.particles) {
    extent = std::max(extent, (q.r - cm).norm());
    heaviest = std::max(heaviest, q.m);
  }
  scene_radius =
      float(preset.container_radius ? *preset.container_radius : std::max(extent * 1.15, 1e-3));
  // A floor below the swarm is in the picture too.
  if (preset.floor) scene_radius = std::max(scene_radius, float(1.2 * (cm.z() - preset.floor->z)));
  heaviest_mass = heaviest;
  // Spheres that would just about touch if the particles filled the scene evenly.
  const double n = double(s.particles.size());
  particle_radius = float(
      std::clamp(0.25 * scene_radius / std::cbrt(n), 0.003 * scene_radius, 0.06 * scene_radius));
  update_followed();
}

bool AppState::select_particle(std::optional<std::size_t> index) {
  if (index && *index >= run->system().particles.size()) return false;
  selected = index;
  update_followed();
  return true;
}

void AppState::update_followed() {
  std::vector<std::size_t> followed;
  const std::size_t n = run->system().particles.size();
  if (n <= kSmallSystem)
    for (std::size_t i = 0; i < n; ++i) followed.push_back(i);
  else if (selected)
    followed.push_back(*selected);
  run->follow(followed);
}

}  // namespace swarmlab
