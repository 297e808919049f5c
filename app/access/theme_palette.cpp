#include "access/theme_palette.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>

namespace swarmlab {
namespace {

constexpr Colour rgb(int r, int g, int b, int a = 255) {
  return {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), std::uint8_t(a)};
}

/// One colour of the palette in both themes. Both columns are required: a row with one colour
/// does not compile.
struct NamedColour {
  constexpr NamedColour(Colour Palette::*field, Colour dark, Colour light)
      : field(field), dark(dark), light(light) {}
  Colour Palette::*field;
  Colour dark, light;
};

/// Every colour of Palette (theme_palette.h, which groups and explains them), in its order, for
/// the dark theme (a screen) and the light one (a projector: near-black on near-white, since the
/// projector washes out mid-tones, so nothing is pale).
constexpr NamedColour kColours[] = {
    {&Palette::window, rgb(23, 26, 33), rgb(250, 250, 250)},
    {&Palette::popup, rgb(20, 22, 28), rgb(255, 255, 255)},
    {&Palette::menu_bar, rgb(31, 33, 43), rgb(232, 234, 238)},
    {&Palette::title, rgb(15, 17, 22), rgb(225, 228, 234)},
    {&Palette::title_active, rgb(30, 52, 84), rgb(200, 212, 235)},
    {&Palette::frame, rgb(41, 46, 61), rgb(228, 231, 238)},
    {&Palette::frame_hovered, rgb(52, 62, 86), rgb(208, 218, 235)},
    {&Palette::frame_active, rgb(60, 76, 110), rgb(186, 204, 232)},
    {&Palette::button, rgb(38, 70, 115), rgb(205, 218, 242)},
    {&Palette::button_hovered, rgb(48, 92, 150), rgb(175, 198, 238)},
    {&Palette::button_active, rgb(30, 60, 110), rgb(150, 180, 232)},
    {&Palette::header, rgb(51, 82, 122), rgb(196, 210, 238)},
    {&Palette::header_hovered, rgb(42, 74, 116), rgb(176, 196, 236)},
    {&Palette::header_active, rgb(45, 75, 120), rgb(160, 186, 232)},
    {&Palette::tab, rgb(35, 52, 80), rgb(214, 222, 238)},
    {&Palette::tab_hovered, rgb(55, 95, 150), rgb(176, 198, 238)},
    {&Palette::tab_active, rgb(48, 82, 130), rgb(160, 186, 232)},
    // Amber, as the selected particle's mark in the view.
    {&Palette::selected_row, rgb(120, 85, 20), rgb(250, 215, 140)},
    {&Palette::text, rgb(240, 242, 245), rgb(12, 12, 16)},
    {&Palette::text_disabled, rgb(190, 192, 200), rgb(70, 72, 80)},
    {&Palette::text_error, rgb(255, 120, 110), rgb(170, 20, 20)},
    {&Palette::text_warning, rgb(255, 200, 110), rgb(135, 75, 0)},
    {&Palette::text_ok, rgb(140, 230, 150), rgb(20, 110, 40)},
    {&Palette::text_key, rgb(255, 217, 115), rgb(120, 60, 0)},
    {&Palette::lesson_title, rgb(255, 217, 115), rgb(20, 50, 130)},
    {&Palette::lesson_keyword, rgb(255, 204, 90), rgb(120, 60, 0)},
    {&Palette::feedback_right, rgb(140, 230, 150), rgb(20, 110, 40)},
    {&Palette::feedback_wrong, rgb(255, 150, 130), rgb(170, 20, 20)},
    {&Palette::feedback_note, rgb(166, 204, 255), rgb(20, 70, 150)},
    {&Palette::slider_grab, rgb(120, 170, 240), rgb(30, 80, 170)},
    {&Palette::check_mark, rgb(130, 190, 255), rgb(20, 70, 160)},
    {&Palette::nav_highlight, rgb(255, 200, 60), rgb(200, 60, 0)},
    {&Palette::border, rgb(110, 110, 128), rgb(110, 112, 120)},
    {&Palette::scrollbar_grab, rgb(105, 108, 120), rgb(120, 122, 130)},
    {&Palette::view_background, rgb(9, 10, 15), rgb(248, 248, 246)},
    {&Palette::view_text, rgb(220, 225, 235), rgb(20, 20, 25)},
    {&Palette::legend_background, rgb(10, 12, 18, 200), rgb(255, 255, 255, 220)},
    {&Palette::container, rgb(150, 195, 240, 150), rgb(40, 90, 160, 200)},
    {&Palette::trail, rgb(200, 210, 255), rgb(70, 70, 120)},
    {&Palette::selected, rgb(255, 235, 120), rgb(170, 60, 0)},
    {&Palette::orbit_ahead, rgb(255, 225, 90, 110), rgb(150, 100, 0, 200)},
    {&Palette::centre_of_mass, rgb(255, 255, 255), rgb(10, 10, 10)},
    {&Palette::spring_attractive, rgb(90, 220, 200, 150), rgb(0, 120, 105, 210)},
    {&Palette::spring_repulsive, rgb(255, 110, 90, 150), rgb(190, 40, 20, 210)},
    {&Palette::ghost, rgb(235, 240, 255), rgb(60, 60, 70)},
    {&Palette::axis_x, rgb(240, 90, 90), rgb(190, 30, 30)},
    {&Palette::axis_y, rgb(110, 220, 110), rgb(20, 120, 20)},
    {&Palette::axis_z, rgb(110, 160, 255), rgb(30, 70, 200)},
    {&Palette::wall_hot, rgb(255, 90, 60, 180), rgb(190, 30, 20, 200)},
    {&Palette::wall_neutral, rgb(235, 235, 240, 180), rgb(60, 60, 70, 200)},
    {&Palette::wall_cold, rgb(110, 170, 255, 180), rgb(20, 60, 190, 200)},
    {&Palette::floor_grid, rgb(200, 180, 130, 170), rgb(100, 80, 40, 190)},
    {&Palette::gravity_arrow, rgb(120, 230, 140, 230), rgb(20, 120, 40)},
    {&Palette::plot_background, rgb(22, 26, 34), rgb(255, 255, 255)},
    {&Palette::plot_grid, rgb(255, 255, 255, 28), rgb(0, 0, 0, 36)},
    {&Palette::plot_axis, rgb(200, 205, 215, 200), rgb(60, 62, 70)},
    {&Palette::plot_text, rgb(215, 220, 230), rgb(15, 15, 20)},
    {&Palette::plot_dim_text, rgb(170, 176, 190), rgb(75, 78, 88)},
    {&Palette::crosshair, rgb(255, 255, 255, 110), rgb(0, 0, 0, 140)},
    {&Palette::pressure, rgb(255, 150, 50), rgb(170, 60, 0)},
    // The raw samples are drawn fainter than their running average, but no fainter than 3:1.
    {&Palette::pressure_each_sample, rgb(255, 150, 50, 150), rgb(220, 120, 40)},
    {&Palette::temperature, rgb(90, 180, 255), rgb(0, 80, 180)},
    {&Palette::temperature_each_sample, rgb(90, 180, 255, 150), rgb(70, 140, 220)},
    {&Palette::kinetic, rgb(255, 205, 70), rgb(150, 100, 0)},
    {&Palette::potential, rgb(120, 200, 255), rgb(0, 110, 170)},
    {&Palette::total_energy, rgb(240, 240, 240), rgb(25, 25, 30)},
    {&Palette::fit, rgb(255, 255, 255, 200), rgb(0, 0, 0, 200)},
    {&Palette::pressure_against_temperature, rgb(230, 120, 255), rgb(140, 40, 180)},
    {&Palette::energy_books_sum, rgb(230, 120, 255), rgb(140, 40, 180)},
    {&Palette::particle_track, rgb(120, 230, 140), rgb(20, 120, 50)},
    {&Palette::particle_start, rgb(255, 90, 90), rgb(190, 30, 30)},
    {&Palette::starting_value, rgb(255, 255, 255, 110), rgb(0, 0, 0, 120)},
    {&Palette::residual, rgb(255, 255, 255, 220), rgb(0, 0, 0, 220)},
    {&Palette::timeline_track, rgb(98, 103, 116), rgb(135, 135, 142)},
    {&Palette::timeline_reached, rgb(150, 210, 255), rgb(15, 45, 115)},
    {&Palette::timeline_stage, rgb(230, 190, 90), rgb(150, 100, 0)},
    {&Palette::timeline_present, rgb(255, 255, 255), rgb(10, 10, 10)},
    {&Palette::timeline_target, rgb(255, 160, 80), rgb(200, 60, 0)},
};

constexpr bool each_colour_once() {
  for (std::size_t i = 0; i < std::size(kColours); ++i)
    for (std::size_t j = i + 1; j < std::size(kColours); ++j)
      if (kColours[i].field == kColours[j].field) return false;
  return true;
}
static_assert(std::size(kColours) == sizeof(Palette) / sizeof(Colour) && each_colour_once(),
              "kColours has one row for each of Palette's colours");

Palette palette_column(Colour NamedColour::*column) {
  Palette p;
  for (const NamedColour& c : kColours) p.*c.field = c.*column;
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
  static const Palette dark = palette_column(&NamedColour::dark),
                       light = palette_column(&NamedColour::light);
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
