#include "ui/plots/plot_figure.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <regex>
#include <string>
#include <vector>

#include "report/svg_plot.h"

using namespace swarmlab;

namespace {

/// Every polyline's stroke in an SVG, in order.
std::vector<std::string> polyline_strokes(const std::string& svg) {
  std::vector<std::string> out;
  const std::regex stroke("<polyline[^>]* stroke=\"(#[0-9a-f]{6})\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), stroke); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[1]);
  return out;
}

}  // namespace

TEST_CASE("plot_figure: the SVG draws each line in the colour the screen draws it") {
  // The wall pressure plot as plots_panel.cpp describes it: the same descriptor the widget
  // draws, in both themes.
  const std::vector<double> t = {0.1, 0.2, 0.3, 0.4}, P = {180, 195, 170, 190},
                            mean = {180, 187, 182, 184};
  for (Theme theme : {Theme::dark, Theme::light}) {
    const Palette& colours = palette(theme);
    PlotSpec spec;
    spec.title = "Wall pressure";
    spec.x = {"t (time)", false, std::nullopt, std::nullopt};
    spec.y = {"P (force/area)", false, std::nullopt, std::nullopt};
    spec.series = {{"each sample", &t, &P, colours.pressure_each_sample.packed(), false, 1.0f},
                   {"running average", &t, &mean, colours.pressure.packed(), false, 2.5f}};
    spec.fits = {{"fit", 150, 0.1, colours.fit.packed()}};
    const std::string svg = report::svg_of(figure_of(spec, colours));
    CAPTURE(theme_name(theme));
    // Colours written independently of css_rgb: the palette's bytes as hex.
    auto hex = [](const Colour& c) {
      char text[8];
      std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
      return std::string(text);
    };
    const std::vector<std::string> expected = {hex(colours.pressure_each_sample),
                                               hex(colours.pressure), hex(colours.fit)};
    CHECK(polyline_strokes(svg) == expected);
    // A translucent line keeps its translucency (the raw samples are fainter on screen).
    if (colours.pressure_each_sample.a < 255) {
      char opacity[32];
      std::snprintf(opacity, sizeof opacity, "stroke-opacity=\"%.2f\"",
                    colours.pressure_each_sample.a / 255.0);
      CHECK(svg.find(opacity) != std::string::npos);
    }
    // On the plot's own background, with its text colour: light lines of the dark theme stay
    // visible, as on screen.
    CHECK(svg.find("<rect width=\"100%\" height=\"100%\" fill=\"" + hex(colours.plot_background) +
                   "\"/>") != std::string::npos);
    CHECK(svg.find("fill=\"" + hex(colours.plot_text) + "\"") != std::string::npos);
  }
}

TEST_CASE("plot_figure: axes keep their quantity and unit, the CSV the plot's numbers") {
  const std::vector<double> x = {1, 2}, y = {3, 4};
  PlotSpec spec;
  spec.title = "t";
  spec.x = {"V (length\u00b3)", false, std::nullopt, std::nullopt};
  spec.y = {"energy", false, std::nullopt, std::nullopt};
  spec.series = {{"E", &x, &y, 0xff0000ffu, false, 2.0f}};
  const report::Figure f = figure_of(spec, palette(Theme::light));
  REQUIRE(f.panels.size() == 1);
  CHECK(f.panels[0].x.label == "V");
  CHECK(f.panels[0].x.unit == "length\u00b3");
  CHECK(f.panels[0].y.label == "energy");
  CHECK(f.panels[0].y.unit.empty());
  REQUIRE(f.panels[0].series.size() == 1);
  CHECK(f.panels[0].series[0].rgb == "#ff0000");  // 0xAABBGGRR: opaque red
  CHECK(f.panels[0].series[0].y == y);
}
