#include "ui/view/scene_overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "i18n/translator.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/physics/orbit_ahead.h"
#include "swarm/physics/regime.h"
#include "ui/kit/theme_style.h"

namespace swarmlab {
namespace {

// Beyond this many particles, springs and all-orbit overlays turn into a grey fog.
constexpr std::size_t kSpringLimit = 30;

using Vec3f = Eigen::Vector3f;

struct Painter {
  ImDrawList* draw;
  const OrbitCamera& camera;
  const ViewRect& rect;
  const Palette& colours;  ///< the app's theme

  ImVec2 at(const ScreenPoint& p) const { return ImVec2(p.x, p.y); }
  ScreenPoint project(const Vec3f& p) const { return camera.project(p, rect); }

  void line(const Vec3f& a, const Vec3f& b, ImU32 colour, float width) const {
    const ScreenPoint pa = project(a), pb = project(b);
    if (pa.visible && pb.visible) draw->AddLine(at(pa), at(pb), colour, width);
  }
  void path(const std::vector<Vec3f>& points, ImU32 colour, float width) const {
    std::vector<ImVec2> screen;
    for (const Vec3f& p : points) {
      const ScreenPoint s = project(p);
      if (!s.visible) {
        if (screen.size() >= 2)
          draw->AddPolyline(screen.data(), int(screen.size()), colour, 0, width);
        screen.clear();
        continue;
      }
      screen.push_back(at(s));
    }
    if (screen.size() >= 2) draw->AddPolyline(screen.data(), int(screen.size()), colour, 0, width);
  }
};

ImU32 with_alpha(ImU32 colour, float alpha) {
  const int a = int(std::clamp(alpha, 0.0f, 1.0f) * float((colour >> IM_COL32_A_SHIFT) & 0xFF));
  return (colour & ~IM_COL32_A_MASK) | (ImU32(a) << IM_COL32_A_SHIFT);
}

/// A hot wall's colour: red when it is hotter than the gas, blue when colder, white when the
/// two agree; the ratio Tw / T sets how far (fully saturated at a factor of 4).
ImU32 wall_temperature_colour(double Tw, double T_gas, const Palette& p) {
  const double x = T_gas > 0 ? std::clamp(std::log(Tw / T_gas) / std::log(4.0), -1.0, 1.0) : 1.0;
  const Colour& end = x > 0 ? p.wall_hot : p.wall_cold;
  const auto mix = [&](std::uint8_t neutral, std::uint8_t far) {
    return std::uint8_t(std::lround(neutral + std::abs(x) * (double(far) - neutral)));
  };
  return Colour{mix(p.wall_neutral.r, end.r), mix(p.wall_neutral.g, end.g),
                mix(p.wall_neutral.b, end.b), mix(p.wall_neutral.a, end.a)}
      .packed();
}

/// Latitude and longitude circles; the far half fainter than the near half, plus the outline,
/// so that the sphere reads as glass around the swarm.
/// `tint`, when given, colours the glass: a hot wall's colour for its temperature; else the
/// theme's container colour.
void draw_container(const Painter& paint, double radius, std::optional<ImU32> tint = {}) {
  const float R = float(radius);
  const Vec3f eye = paint.camera.eye();
  const ImU32 near_colour = tint ? *tint : paint.colours.container.packed();
  const ImU32 far_colour = with_alpha(near_colour, 0.36f);
  constexpr int kSegments = 72;
  auto circle_segments = [&](auto point_at) {
    for (int k = 0; k < kSegments; ++k) {
      const Vec3f a = point_at(2 * float(M_PI) * float(k) / kSegments);
      const Vec3f b = point_at(2 * float(M_PI) * float(k + 1) / kSegments);
      const bool near_side = (0.5f * (a + b)).dot(eye) > R * R;
      paint.line(a, b, near_side ? near_colour : far_colour, near_side ? 1.4f : 1.0f);
    }
  };
  for (int lat = -2; lat <= 2; ++lat) {
    const float z = R * std::sin(float(lat) * float(M_PI) / 6), rho = std::sqrt(R * R - z * z);
    circle_segments([&](float phi) { return Vec3f(rho * std::cos(phi), rho * std::sin(phi), z); });
  }
  for (int lon = 0; lon < 6; ++lon) {
    const float phi = float(lon) * float(M_PI) / 6;
    circle_segments([&](float theta) {
      return Vec3f(R * std::cos(theta) * std::cos(phi), R * std::cos(theta) * std::sin(phi),
                   R * std::sin(theta));
    });
  }
  // The silhouette: where the lines of sight touch the sphere.
  const float d = eye.norm();
  if (d > R) {
    const Vec3f n = eye / d;
    const Vec3f centre = n * (R * R / d);
    const float r = R * std::sqrt(1 - R * R / (d * d));
    const Vec3f u = n.cross(std::abs(n.z()) < 0.9f ? Vec3f::UnitZ() : Vec3f::UnitX()).normalized();
    const Vec3f w = n.cross(u);
    std::vector<Vec3f> outline;
    for (int k = 0; k <= 96; ++k) {
      const float a = 2 * float(M_PI) * float(k) / 96;
      outline.push_back(centre + r * (std::cos(a) * u + std::sin(a) * w));
    }
    std::vector<ImVec2> screen;
    for (const Vec3f& p : outline) screen.push_back(paint.at(paint.project(p)));
    paint.draw->AddConvexPolyFilled(screen.data(), int(screen.size()) - 1,
                                    with_alpha(near_colour, 0.1f));
    paint.path(outline, with_alpha(near_colour | IM_COL32_A_MASK, 0.9f), 2.0f);
  }
}

void draw_springs(const Painter& paint, const swarm::System& s, SpringOverlay mode) {
  const std::size_t n = s.particles.size();
  if (mode == SpringOverlay::off || n > kSpringLimit || s.J == 0) return;
  const ImU32 colour =
      s.J > 0 ? paint.colours.spring_attractive.packed() : paint.colours.spring_repulsive.packed();
  const double M = swarm::total_mass(s);
  const Vec3f cm = swarm::cm_position(s).cast<float>();
  double k_max = 0;
  for (const auto& p : s.particles)
    k_max = std::max(k_max, mode == SpringOverlay::pairs ? p.m * p.m : M * p.m);
  if (mode == SpringOverlay::pairs) {
    // k_ij = J m_i m_j: width proportional to k, the stiffest pair 7 px wide.
    double pair_max = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        pair_max = std::max(pair_max, s.particles[i].m * s.particles[j].m);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const double k = s.particles[i].m * s.particles[j].m;
        paint.line(s.particles[i].r.cast<float>(), s.particles[j].r.cast<float>(), colour,
                   1.0f + 6.0f * float(k / pair_max));
      }
  } else {
    // k_i = J M m_i to the centre of mass.
    for (const auto& p : s.particles)
      paint.line(p.r.cast<float>(), cm, colour, 1.0f + 6.0f * float(M * p.m / k_max));
  }
}

/// The analytic path of a particle from now on (swarm::OrbitsAhead): one period when J > 0, a
/// stretch of the runaway or of the straight line otherwise.
std::vector<Vec3f> orbit_ahead(const swarm::OrbitsAhead& orbits, const swarm::Particle& p,
                               float scene_radius) {
  const double k = orbits.stiffness();
  double span;
  if (k > 0)
    span = swarm::period_of(k);
  else if (k < 0)
    span = 2.5 / swarm::omega_of(k);
  else
    span = 2 * scene_radius / std::max((p.v - orbits.cm_velocity()).norm(), 1e-12);
  std::vector<Vec3f> out;
  for (const swarm::Vec3& r : orbits.path(p, span, 180)) out.push_back(r.cast<float>());
  return out;
}

void draw_axes(const AppState& state, ImDrawList* draw) {
  // A small triad in the lower right corner turning with the camera.
  const ViewRect& rect = state.layout.view;
  const float font = ImGui::GetFontSize();
  const ImVec2 origin(rect.x + rect.width - 3.0f * font, rect.y + rect.height - 3.0f * font);
  const Eigen::Matrix4f view = state.camera.view();
  const char* names[] = {"x", "y", "z"};
  const Palette& theme = palette(state.presentation.theme);
  const ImU32 colours[] = {theme.axis_x.packed(), theme.axis_y.packed(), theme.axis_z.packed()};
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3f d = view.block<3, 3>(0, 0).col(a);
    const ImVec2 tip(origin.x + d.x() * 1.8f * font, origin.y - d.y() * 1.8f * font);
    draw->AddLine(origin, tip, colours[a], 2.0f);
    draw->AddText(ImVec2(tip.x - 0.3f * font, tip.y - 0.6f * font), colours[a], names[a]);
  }
}

void draw_legend(AppState& state, ImDrawList* draw) {
  const ViewRect& rect = state.layout.view;
  const float font = ImGui::GetFontSize();
  const float width = std::min(16.0f * font, rect.width * 0.4f), height = 0.8f * font;
  const ImVec2 low(rect.x + 1.0f * font, rect.y + rect.height - 2.2f * font);
  draw->AddRectFilled(ImVec2(low.x - 0.5f * font, low.y - 1.6f * font),
                      ImVec2(low.x + width + 0.5f * font, low.y + height + 1.5f * font),
                      palette(state.presentation.theme).legend_background.packed(), 4.0f);
  constexpr int kSteps = 48;
  for (int k = 0; k < kSteps; ++k) {
    const float x0 = low.x + width * float(k) / kSteps, x1 = low.x + width * float(k + 1) / kSteps;
    draw->AddRectFilled(
        ImVec2(x0, low.y), ImVec2(x1 + 0.5f, low.y + height),
        particle_colour(float(k + 0.5f) / kSteps, state.presentation.theme).packed());
  }
  const ImU32 text_colour = palette(state.presentation.theme).view_text.packed();
  draw->AddText(ImVec2(low.x, low.y - 1.3f * font), text_colour,
                legend_title(state.view.colour_by));
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", state.colour_scale.lo);
  draw->AddText(ImVec2(low.x, low.y + height + 0.1f * font), text_colour,
                translator().numbers(text).c_str());
  std::snprintf(text, sizeof text, "%.3g", state.colour_scale.hi);
  const std::string hi = translator().numbers(text);
  const float w = ImGui::CalcTextSize(hi.c_str()).x;
  draw->AddText(ImVec2(low.x + width - w, low.y + height + 0.1f * font),
                text_colour, hi.c_str());
}

/// The floor z = h as a grid square about the centre of mass, out to the scene's radius.
void draw_floor(const Painter& paint, double h, const swarm::Vec3& cm, float extent) {
  const float z = float(h), x0 = float(cm.x()), y0 = float(cm.y());
  constexpr int kLines = 8;
  const ImU32 colour = paint.colours.floor_grid.packed();
  for (int k = -kLines; k <= kLines; ++k) {
    const float o = extent * float(k) / kLines;
    paint.line(Vec3f(x0 - extent, y0 + o, z), Vec3f(x0 + extent, y0 + o, z), colour, 1.0f);
    paint.line(Vec3f(x0 + o, y0 - extent, z), Vec3f(x0 + o, y0 + extent, z), colour, 1.0f);
  }
}

/// Gravity as an arrow from beside the centre of mass along g, a third of the scene long.
void draw_gravity_arrow(const Painter& paint, const swarm::Vec3& g, const swarm::Vec3& cm,
                        float extent, float font) {
  if (g.norm() == 0) return;
  const Vec3f dir = g.normalized().cast<float>();
  const Vec3f side = dir.cross(std::abs(dir.z()) < 0.9f ? Vec3f::UnitZ() : Vec3f::UnitX()).normalized();
  const Vec3f start = cm.cast<float>() + side * (0.8f * extent) - dir * (0.15f * extent);
  const Vec3f end = start + dir * (0.35f * extent);
  const ImU32 colour = paint.colours.gravity_arrow.packed();
  paint.line(start, end, colour, 2.5f);
  const ScreenPoint a = paint.project(start), b = paint.project(end);
  if (!a.visible || !b.visible) return;
  const float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
  if (len < 1) return;
  const float ux = dx / len, uy = dy / len, head = 0.7f * font;
  paint.draw->AddTriangleFilled(ImVec2(b.x + ux * head, b.y + uy * head),
                                ImVec2(b.x - uy * head * 0.6f, b.y + ux * head * 0.6f),
                                ImVec2(b.x + uy * head * 0.6f, b.y - ux * head * 0.6f), colour);
  char label[48];
  std::snprintf(label, sizeof label, tr("g = %.3g"), g.norm());
  paint.draw->AddText(ImVec2(a.x + 0.5f * font, a.y - 1.2f * font), colour,
                      translator().numbers(label).c_str());
}

}  // namespace

void draw_scene_overlay(AppState& state) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ViewRect& rect = state.layout.view;
  draw->PushClipRect(ImVec2(rect.x, rect.y), ImVec2(rect.x + rect.width, rect.y + rect.height),
                     false);
  const Painter paint{draw, state.camera, rect, palette(state.presentation.theme)};
  const swarm::System& s = state.run->system();
  const float font = ImGui::GetFontSize();
  const Palette& theme = paint.colours;

  if (state.view.container)
    if (const auto R = state.run->primary().engine().container_radius()) {
      if (const auto Tw = state.preset.wall_temperature)
        draw_container(paint, *R,
                       wall_temperature_colour(*Tw, swarm::kinetic_temperature(s), theme));
      else
        draw_container(paint, *R);
    }
  draw_springs(paint, s, state.view.springs);
  if (state.preset.floor)
    draw_floor(paint, state.preset.floor->z, swarm::cm_position(s), state.scene_radius);
  if (state.preset.gravity)
    draw_gravity_arrow(paint, *state.preset.gravity, swarm::cm_position(s), state.scene_radius,
                       font);

  if (state.view.trails)
    for (const Trail& trail : state.run->trails()) {
      // Older points fade out, so the direction of motion reads at a glance.
      const std::size_t n = trail.points.size();
      const ImU32 colour = state.selected && *state.selected == trail.particle
                               ? theme.selected.packed()
                               : theme.trail.packed();
      for (std::size_t k = 1; k < n; ++k)
        paint.line(trail.points[k - 1], trail.points[k],
                   with_alpha(colour, 0.1f + 0.75f * float(k) / float(n)), 1.6f);
    }

  // In a small system every orbit is drawn faintly: the closed ellipses with one common period
  // are the paper's first result.
  std::optional<swarm::OrbitsAhead> orbits;  // O(N) once, only when orbits are drawn
  // The orbit ahead is the isolated swarm's; gravity, a floor or drag bend it, so none is drawn.
  const bool forced = state.preset.gravity || state.preset.floor || state.preset.drag;
  if (state.view.orbit && !forced) orbits.emplace(s);
  if (orbits && s.particles.size() <= kSpringLimit)
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      if (!state.selected || *state.selected != i)
        paint.path(orbit_ahead(*orbits, s.particles[i], state.scene_radius),
                   theme.orbit_ahead.packed(), 1.3f);
  if (state.selected && *state.selected < s.particles.size()) {
    const std::size_t i = *state.selected;
    if (orbits)
      paint.path(orbit_ahead(*orbits, s.particles[i], state.scene_radius),
                 with_alpha(theme.selected.packed(), 0.86f), 2.2f);
    const ScreenPoint p = paint.project(s.particles[i].r.cast<float>());
    if (p.visible) {
      draw->AddCircle(paint.at(p), 0.9f * font, theme.selected.packed(), 24, 2.0f);
      char label[64];
      std::snprintf(label, sizeof label, tr("#%zu  m = %.3g"), i + 1, s.particles[i].m);
      draw->AddText(ImVec2(p.x + 1.0f * font, p.y - 1.4f * font), theme.selected.packed(),
                    translator().numbers(label).c_str());
    }
  }

  if (state.view.centre_of_mass) {
    // An empty circle with a cross, as in the paper's Fig. 1.
    const ScreenPoint c = paint.project(swarm::cm_position(s).cast<float>());
    if (c.visible) {
      const ImVec2 at = paint.at(c);
      draw->AddCircle(at, 0.6f * font, theme.centre_of_mass.packed(), 24, 2.0f);
      draw->AddLine(ImVec2(at.x - 0.9f * font, at.y), ImVec2(at.x + 0.9f * font, at.y),
                    theme.centre_of_mass.packed(), 1.5f);
      draw->AddLine(ImVec2(at.x, at.y - 0.9f * font), ImVec2(at.x, at.y + 0.9f * font),
                    theme.centre_of_mass.packed(), 1.5f);
      draw->AddText(ImVec2(at.x + 0.8f * font, at.y + 0.2f * font), theme.centre_of_mass.packed(),
                    tr("CM"));
    }
  }
  if (state.view.axes) draw_axes(state, draw);
  draw_legend(state, draw);
  draw->PopClipRect();
}

}  // namespace swarmlab
