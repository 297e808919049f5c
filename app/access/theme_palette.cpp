#include "access/theme_palette.h"

#include <algorithm>
#include <cmath>

namespace swarmlab {
namespace {

constexpr Colour rgb(int r, int g, int b, int a = 255) {
  return {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), std::uint8_t(a)};
}

Palette dark_palette() {
  Palette p;
  p.window = rgb(23, 26, 33);
  p.popup = rgb(20, 22, 28);
  p.menu_bar = rgb(31, 33, 43);
  p.title = rgb(15, 17, 22);
  p.title_active = rgb(30, 52, 84);
  p.frame = rgb(41, 46, 61);
  p.frame_hovered = rgb(52, 62, 86);
  p.frame_active = rgb(60, 76, 110);
  p.button = rgb(38, 70, 115);
  p.button_hovered = rgb(48, 92, 150);
  p.button_active = rgb(30, 60, 110);
  p.header = rgb(51, 82, 122);
  p.header_hovered = rgb(42, 74, 116);
  p.header_active = rgb(45, 75, 120);
  p.tab = rgb(35, 52, 80);
  p.tab_hovered = rgb(55, 95, 150);
  p.tab_active = rgb(48, 82, 130);
  p.selected_row = rgb(120, 85, 20);  // amber, as the selected particle's mark in the view
  p.text = rgb(240, 242, 245);
  p.text_disabled = rgb(190, 192, 200);
  p.text_error = rgb(255, 120, 110);
  p.text_warning = rgb(255, 200, 110);
  p.text_ok = rgb(140, 230, 150);
  p.text_key = rgb(255, 217, 115);
  p.lesson_title = rgb(255, 217, 115);
  p.lesson_keyword = rgb(255, 204, 90);
  p.feedback_right = rgb(140, 230, 150);
  p.feedback_wrong = rgb(255, 150, 130);
  p.feedback_note = rgb(166, 204, 255);
  p.slider_grab = rgb(120, 170, 240);
  p.check_mark = rgb(130, 190, 255);
  p.nav_highlight = rgb(255, 200, 60);
  p.border = rgb(110, 110, 128);
  p.scrollbar_grab = rgb(105, 108, 120);
  p.view_background = rgb(9, 10, 15);
  p.view_text = rgb(220, 225, 235);
  p.legend_background = rgb(10, 12, 18, 200);
  p.container = rgb(150, 195, 240, 150);
  p.trail = rgb(200, 210, 255);
  p.selected = rgb(255, 235, 120);
  p.orbit_ahead = rgb(255, 225, 90, 110);
  p.centre_of_mass = rgb(255, 255, 255);
  p.spring_attractive = rgb(90, 220, 200, 150);
  p.spring_repulsive = rgb(255, 110, 90, 150);
  p.ghost = rgb(235, 240, 255);
  p.axis_x = rgb(240, 90, 90);
  p.axis_y = rgb(110, 220, 110);
  p.axis_z = rgb(110, 160, 255);
  p.wall_hot = rgb(255, 90, 60, 180);
  p.wall_neutral = rgb(235, 235, 240, 180);
  p.wall_cold = rgb(110, 170, 255, 180);
  p.floor_grid = rgb(200, 180, 130, 170);
  p.gravity_arrow = rgb(120, 230, 140, 230);
  p.plot_background = rgb(22, 26, 34);
  p.plot_grid = rgb(255, 255, 255, 28);
  p.plot_axis = rgb(200, 205, 215, 200);
  p.plot_text = rgb(215, 220, 230);
  p.plot_dim_text = rgb(170, 176, 190);
  p.crosshair = rgb(255, 255, 255, 110);
  p.pressure = rgb(255, 150, 50);
  // The raw samples are drawn fainter than their running average, but no fainter than 3:1.
  p.pressure_each_sample = rgb(255, 150, 50, 150);
  p.temperature = rgb(90, 180, 255);
  p.temperature_each_sample = rgb(90, 180, 255, 150);
  p.kinetic = rgb(255, 205, 70);
  p.potential = rgb(120, 200, 255);
  p.total_energy = rgb(240, 240, 240);
  p.fit = rgb(255, 255, 255, 200);
  p.pressure_against_temperature = rgb(230, 120, 255);
  p.energy_books_sum = rgb(230, 120, 255);
  p.particle_track = rgb(120, 230, 140);
  p.particle_start = rgb(255, 90, 90);
  p.starting_value = rgb(255, 255, 255, 110);
  p.residual = rgb(255, 255, 255, 220);
  p.timeline_track = rgb(98, 103, 116);
  p.timeline_reached = rgb(150, 210, 255);
  p.timeline_stage = rgb(230, 190, 90);
  p.timeline_present = rgb(255, 255, 255);
  p.timeline_target = rgb(255, 160, 80);
  return p;
}

/// Near-black on near-white: the projector washes out mid-tones, so nothing is pale.
Palette light_palette() {
  Palette p;
  p.window = rgb(250, 250, 250);
  p.popup = rgb(255, 255, 255);
  p.menu_bar = rgb(232, 234, 238);
  p.title = rgb(225, 228, 234);
  p.title_active = rgb(200, 212, 235);
  p.frame = rgb(228, 231, 238);
  p.frame_hovered = rgb(208, 218, 235);
  p.frame_active = rgb(186, 204, 232);
  p.button = rgb(205, 218, 242);
  p.button_hovered = rgb(175, 198, 238);
  p.button_active = rgb(150, 180, 232);
  p.header = rgb(196, 210, 238);
  p.header_hovered = rgb(176, 196, 236);
  p.header_active = rgb(160, 186, 232);
  p.tab = rgb(214, 222, 238);
  p.tab_hovered = rgb(176, 198, 238);
  p.tab_active = rgb(160, 186, 232);
  p.selected_row = rgb(250, 215, 140);
  p.text = rgb(12, 12, 16);
  p.text_disabled = rgb(70, 72, 80);
  p.text_error = rgb(170, 20, 20);
  p.text_warning = rgb(135, 75, 0);
  p.text_ok = rgb(20, 110, 40);
  p.text_key = rgb(120, 60, 0);
  p.lesson_title = rgb(20, 50, 130);
  p.lesson_keyword = rgb(120, 60, 0);
  p.feedback_right = rgb(20, 110, 40);
  p.feedback_wrong = rgb(170, 20, 20);
  p.feedback_note = rgb(20, 70, 150);
  p.slider_grab = rgb(30, 80, 170);
  p.check_mark = rgb(20, 70, 160);
  p.nav_highlight = rgb(200, 60, 0);
  p.border = rgb(110, 112, 120);
  p.scrollbar_grab = rgb(120, 122, 130);
  p.view_background = rgb(248, 248, 246);
  p.view_text = rgb(20, 20, 25);
  p.legend_background = rgb(255, 255, 255, 220);
  p.container = rgb(40, 90, 160, 200);
  p.trail = rgb(70, 70, 120);
  p.selected = rgb(170, 60, 0);
  p.orbit_ahead = rgb(150, 100, 0, 200);
  p.centre_of_mass = rgb(10, 10, 10);
  p.spring_attractive = rgb(0, 120, 105, 210);
  p.spring_repulsive = rgb(190, 40, 20, 210);
  p.ghost = rgb(60, 60, 70);
  p.axis_x = rgb(190, 30, 30);
  p.axis_y = rgb(20, 120, 20);
  p.axis_z = rgb(30, 70, 200);
  p.wall_hot = rgb(190, 30, 20, 200);
  p.wall_neutral = rgb(60, 60, 70, 200);
  p.wall_cold = rgb(20, 60, 190, 200);
  p.floor_grid = rgb(100, 80, 40, 190);
  p.gravity_arrow = rgb(20, 120, 40);
  p.plot_background = rgb(255, 255, 255);
  p.plot_grid = rgb(0, 0, 0, 36);
  p.plot_axis = rgb(60, 62, 70);
  p.plot_text = rgb(15, 15, 20);
  p.plot_dim_text = rgb(75, 78, 88);
  p.crosshair = rgb(0, 0, 0, 140);
  p.pressure = rgb(170, 60, 0);
  p.pressure_each_sample = rgb(220, 120, 40);
  p.temperature = rgb(0, 80, 180);
  p.temperature_each_sample = rgb(70, 140, 220);
  p.kinetic = rgb(150, 100, 0);
  p.potential = rgb(0, 110, 170);
  p.total_energy = rgb(25, 25, 30);
  p.fit = rgb(0, 0, 0, 200);
  p.pressure_against_temperature = rgb(140, 40, 180);
  p.energy_books_sum = rgb(140, 40, 180);
  p.particle_track = rgb(20, 120, 50);
  p.particle_start = rgb(190, 30, 30);
  p.starting_value = rgb(0, 0, 0, 120);
  p.residual = rgb(0, 0, 0, 220);
  p.timeline_track = rgb(135, 135, 142);
  p.timeline_reached = rgb(15, 45, 115);
  p.timeline_stage = rgb(150, 100, 0);
  p.timeline_present = rgb(10, 10, 10);
  p.timeline_target = rgb(200, 60, 0);
  return p;
}

/// Luminance at least this on the dark view background (L = 0.0032) keeps 3:1:
/// (0.115 + 0.05) / (0.0032 + 0.05) = 3.1. Only Turbo's darkest blues are brightened.
constexpr double kDarkViewParticleLuminance = 0.115;
/// Luminance at most this on the light view background (L = 0.9375) keeps 3:1:
/// (0.9375 + 0.05) / (0.27 + 0.05) = 3.09.
constexpr double kLightViewParticleLuminance = 0.27;

}  // namespace

Colour plot_line_colour(Colour c, Theme theme) {
  // White plots (L = 1): (1 + 0.05) / (0.3 + 0.05) = 3. Dark plots (L = 0.0098):
  // (0.135 + 0.05) / (0.0098 + 0.05) = 3.1.
  return theme == Theme::light ? darkened_to(c, 0.29) : brightened_to(c, 0.135);
}

const char* theme_name(Theme theme) { return theme == Theme::light ? "light" : "dark"; }

const Palette& palette(Theme theme) {
  static const Palette dark = dark_palette(), light = light_palette();
  return theme == Theme::light ? light : dark;
}

Colour turbo_colour(float x) {
  // Polynomial fit of the Turbo map (Mikhailov, Google AI blog, 2019), kept away from its
  // darkest ends.
  const double t = 0.06 + 0.9 * std::clamp(double(x), 0.0, 1.0);
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
  const double r = 0.13572138 + 4.61539260 * t - 42.66032258 * t2 + 132.13108234 * t3 -
                   152.94239396 * t4 + 59.28637943 * t5;
  const double g = 0.09140261 + 2.19418839 * t + 4.84296658 * t2 - 14.18503333 * t3 +
                   4.27729857 * t4 + 2.82956604 * t5;
  const double b = 0.10667330 + 12.64194608 * t - 60.58204836 * t2 + 110.36276771 * t3 -
                   89.90310912 * t4 + 27.34824973 * t5;
  auto byte = [](double c) { return std::uint8_t(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); };
  return {byte(r), byte(g), byte(b), 255};
}

Colour particle_colour(float x, Theme theme) {
  // Every particle is coloured every frame: the map is worked out once, at 1/255 steps (finer
  // than the eye tells apart on a continuous map).
  struct Map {
    Colour at[256];
    explicit Map(Theme theme) {
      for (int k = 0; k < 256; ++k) {
        const Colour c = turbo_colour(float(k) / 255);
        at[k] = theme == Theme::light ? darkened_to(c, kLightViewParticleLuminance)
                                      : brightened_to(c, kDarkViewParticleLuminance);
      }
    }
  };
  static const Map dark(Theme::dark), light(Theme::light);
  const float clamped = std::isnan(x) ? 0.0f : std::clamp(x, 0.0f, 1.0f);
  return (theme == Theme::light ? light : dark).at[int(std::lround(clamped * 255))];
}

}  // namespace swarmlab
