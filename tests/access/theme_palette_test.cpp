#include "access/theme_palette.h"

#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

using namespace swarmlab;

namespace {

// WCAG 2.x level AA: 4.5:1 for text (1.4.3), 3:1 for lines, controls and focus (1.4.11).
constexpr double kText = 4.5, kGraphics = 3.0;

using Named = std::pair<const char*, Colour>;

void check_all(const char* theme, const std::vector<Named>& foreground,
               const std::vector<Named>& background, double least) {
  for (const Named& f : foreground)
    for (const Named& b : background) {
      const double ratio = contrast_ratio(f.second, b.second);
      const std::string what = std::string(theme) + ": " + f.first + " on " + b.first;
      INFO(what << " = " << ratio << ":1");
      CHECK(ratio >= least);
    }
}

void check_theme(Theme theme) {
  const Palette& p = palette(theme);
  const char* name = theme_name(theme);
  // Translucent panel backgrounds are seen over the window.
  auto on_window = [&](Colour c) { return over(c, p.window); };
  const std::vector<Named> panel_backgrounds = {{"window", p.window},
                                                {"popup", p.popup},
                                                {"menu bar", p.menu_bar},
                                                {"title", p.title},
                                                {"active title", p.title_active},
                                                {"field", on_window(p.frame)},
                                                {"hovered field", on_window(p.frame_hovered)},
                                                {"active field", on_window(p.frame_active)},
                                                {"button", on_window(p.button)},
                                                {"hovered button", on_window(p.button_hovered)},
                                                {"pressed button", on_window(p.button_active)},
                                                {"header", on_window(p.header)},
                                                {"hovered header", on_window(p.header_hovered)},
                                                {"active header", on_window(p.header_active)},
                                                {"tab", on_window(p.tab)},
                                                {"hovered tab", on_window(p.tab_hovered)},
                                                {"active tab", on_window(p.tab_active)},
                                                {"selected table row", p.selected_row}};
  // Every panel text on every panel background.
  check_all(name, {{"text", p.text}}, panel_backgrounds, kText);
  // The dimmed text (units, hints, the title, menu shortcuts) where ImGui draws it: on the
  // panels, fields and menus, and on the highlighted menu item.
  check_all(name, {{"dimmed text", p.text_disabled}},
            {{"window", p.window},
             {"popup", p.popup},
             {"menu bar", p.menu_bar},
             {"title", p.title},
             {"field", on_window(p.frame)},
             {"highlighted menu item", on_window(p.header_hovered)}},
            kText);
  // Coloured messages appear on the window and in tooltips.
  check_all(name,
            {{"error", p.text_error},
             {"warning", p.text_warning},
             {"ok", p.text_ok},
             {"key", p.text_key}},
            {{"window", p.window}, {"popup", p.popup}}, kText);
  // A lesson's title, keywords and feedback on the panel, in the step's box (a child window
  // drawn on the panel), in the welcome window and in tooltips. Presentation mode draws the
  // light theme, so the light palette's check covers it.
  check_all(name,
            {{"lesson title", p.lesson_title},
             {"lesson keyword", p.lesson_keyword},
             {"feedback: right", p.feedback_right},
             {"feedback: not yet", p.feedback_wrong},
             {"feedback: recorded", p.feedback_note}},
            {{"window", p.window}, {"popup", p.popup}, {"field", on_window(p.frame)}}, kText);
  // Marks a student must see on what they sit on.
  check_all(name, {{"slider grab", p.slider_grab}, {"check mark", p.check_mark}},
            {{"field", on_window(p.frame)}, {"hovered field", on_window(p.frame_hovered)}},
            kGraphics);
  check_all(name,
            {{"focus highlight", p.nav_highlight},
             {"border", p.border},
             {"scroll bar", p.scrollbar_grab}},
            {{"window", p.window}, {"popup", p.popup}}, kGraphics);

  // The 3D view: text on the view and on the legend's box, lines on the view.
  const Colour legend = over(p.legend_background, p.view_background);
  check_all(name, {{"view text", p.view_text}}, {{"view", p.view_background}, {"legend", legend}},
            kText);
  check_all(name,
            {{"container", p.container},
             {"trail", p.trail},
             {"selected", p.selected},
             {"orbit ahead", p.orbit_ahead},
             {"centre of mass", p.centre_of_mass},
             {"attracting springs", p.spring_attractive},
             {"repelling springs", p.spring_repulsive},
             {"ghost", p.ghost},
             {"x axis", p.axis_x},
             {"y axis", p.axis_y},
             {"z axis", p.axis_z},
             {"hot wall", p.wall_hot},
             {"wall as warm as the gas", p.wall_neutral},
             {"cold wall", p.wall_cold},
             {"floor", p.floor_grid},
             {"gravity", p.gravity_arrow}},
            {{"view", p.view_background}}, kGraphics);

  // Plots: labels are text, every series and fit line a graphic; the legend box is the plot
  // background.
  check_all(name, {{"plot text", p.plot_text}, {"tick labels", p.plot_dim_text}},
            {{"plot", p.plot_background}}, kText);
  const std::vector<Named> series = {{"pressure", p.pressure},
                                     {"pressure, each sample", p.pressure_each_sample},
                                     {"temperature", p.temperature},
                                     {"temperature, each sample", p.temperature_each_sample},
                                     {"kinetic energy", p.kinetic},
                                     {"potential energy", p.potential},
                                     {"total energy", p.total_energy},
                                     {"power-law fit", p.fit},
                                     {"P against T", p.pressure_against_temperature},
                                     {"energy books' sum", p.energy_books_sum},
                                     {"x(t)", p.particle_track},
                                     {"x(t) start", p.particle_start},
                                     {"starting value", p.starting_value},
                                     {"residuals", p.residual}};
  check_all(name, series, {{"plot", p.plot_background}}, kGraphics);
  check_all(name, {{"axis", p.plot_axis}, {"cross-hair", p.crosshair}},
            {{"plot", p.plot_background}}, kGraphics);
  // The hover tooltip marks each series' line with a swatch of its colour on the popup.
  check_all(name, series, {{"tooltip", p.popup}}, kGraphics);

  // The timeline strip (the window, 85% opaque over the view): the bar and the marks above
  // and across it on the strip, and the part computed so far apart from the rest of the bar.
  Colour strip_window = p.window;
  strip_window.a = 217;
  const Colour strip = over(strip_window, p.view_background);
  check_all(name,
            {{"timeline bar", p.timeline_track},
             {"stage start", p.timeline_stage},
             {"present", p.timeline_present},
             {"seek target", p.timeline_target}},
            {{"timeline strip", strip}}, kGraphics);
  check_all(name, {{"time computed", p.timeline_reached}}, {{"timeline bar", p.timeline_track}},
            kGraphics);
}

}  // namespace

TEST_CASE("dark theme: every text at 4.5:1 and every line and mark at 3:1 (WCAG AA)") {
  check_theme(Theme::dark);
}

TEST_CASE("light theme: every text at 4.5:1 and every line and mark at 3:1 (WCAG AA)") {
  check_theme(Theme::light);
}

TEST_CASE("the raw samples stay fainter than their running average, so the two read apart") {
  for (Theme theme : {Theme::dark, Theme::light}) {
    const Palette& p = palette(theme);
    CHECK(contrast_ratio(p.pressure_each_sample, p.plot_background) <
          contrast_ratio(p.pressure, p.plot_background));
    CHECK(contrast_ratio(p.temperature_each_sample, p.plot_background) <
          contrast_ratio(p.temperature, p.plot_background));
  }
}

TEST_CASE("every particle colour stands out from the view at 3:1 in both themes") {
  for (Theme theme : {Theme::dark, Theme::light})
    for (int k = 0; k <= 200; ++k) {
      const float x = float(k) / 200;
      const double ratio =
          contrast_ratio(particle_colour(x, theme), palette(theme).view_background);
      INFO(std::string(theme_name(theme)) << " view, colour map at " << x << ": " << ratio << ":1");
      CHECK(ratio >= kGraphics);
    }
}

TEST_CASE("plot_line_colour: any line colour (white, yellow, navy) at 3:1 on either plot") {
  const Colour lines[] = {{255, 255, 255}, {255, 230, 60}, {20, 30, 110}, {0, 0, 0}, {90, 200, 90}};
  for (Theme theme : {Theme::dark, Theme::light})
    for (const Colour& c : lines) {
      const double ratio =
          contrast_ratio(plot_line_colour(c, theme), palette(theme).plot_background);
      INFO(std::string(theme_name(theme))
           << ": " << int(c.r) << "," << int(c.g) << "," << int(c.b) << " at " << ratio << ":1");
      CHECK(ratio >= kGraphics);
    }
  // A colour that already stands out is kept.
  CHECK(plot_line_colour({255, 150, 50}, Theme::dark).packed() == Colour{255, 150, 50}.packed());
}

TEST_CASE("the light theme's colour map keeps its order: low blue, high red, as on the dark") {
  const Colour low = particle_colour(0, Theme::light), high = particle_colour(1, Theme::light);
  CHECK(low.b > low.r);
  CHECK(high.r > high.b);
  // The dark view keeps Turbo itself where it is bright enough.
  CHECK(particle_colour(128.0f / 255, Theme::dark).packed() == turbo_colour(128.0f / 255).packed());
  // Outside [0, 1] (a particle beyond the scale's range): the end colours.
  CHECK(particle_colour(-3, Theme::light).packed() == particle_colour(0, Theme::light).packed());
  CHECK(particle_colour(7, Theme::dark).packed() == particle_colour(1, Theme::dark).packed());
}
