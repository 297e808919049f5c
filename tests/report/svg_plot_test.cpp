#include "report/svg_plot.h"

#include <doctest/doctest.h>

#include <regex>
#include <string>
#include <vector>

using namespace swarmlab;

namespace {

struct Box {
  double x, y, w, h;
};

/// The first <rect> with x, y, width and height whose attributes go on with `then` (a regex).
Box rect_with(const std::string& svg, const std::string& then) {
  const std::regex rect("<rect x=\"([-0-9.]+)\" y=\"([-0-9.]+)\" width=\"([-0-9.]+)\" "
                        "height=\"([-0-9.]+)\"" + then);
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, rect));
  return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stod(m[4])};
}

/// The legend's box: the one rect with rounded corners (the frame and background have none).
Box legend_box(const std::string& svg) { return rect_with(svg, "[^>]* rx=\"3\""); }

/// The plot area: the frame drawn over the data (fill none).
Box plot_frame(const std::string& svg) { return rect_with(svg, " fill=\"none\""); }

double svg_height(const std::string& svg) {
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("<svg[^>]* height=\"([0-9.]+)\"")));
  return std::stod(m[1]);
}

/// A panel of two named series over x, y in [0, 1]; `x`, `y` are the second's points (the
/// first holds the range's ends, which lie on the frame, outside any inset corner box).
report::Figure figure_with(const std::vector<double>& x, const std::vector<double>& y) {
  report::Panel panel;
  panel.x = {"volume V", "length³"};
  panel.y = {"temperature T", "energy"};
  panel.series.push_back({"the range", {0, 1}, {0, 1}, report::Mark::points});
  panel.series.push_back({"a series with a long name, as an overlay's legend has", x, y,
                          report::Mark::points, 1});
  report::Figure figure;
  figure.title = "legend";
  figure.panels.push_back(panel);
  return figure;
}

}  // namespace

TEST_CASE("svg_plot: the legend takes a free corner, and goes under the panel when none is free") {
  // Points near three corners: the top-left corner is free.
  const std::string three = report::svg_of(figure_with({0.03, 0.97, 0.97}, {0.03, 0.03, 0.97}));
  const Box frame3 = plot_frame(three), legend3 = legend_box(three);
  CHECK(legend3.y < frame3.y + 0.5 * frame3.h);  // inside, at the top
  CHECK(legend3.x < frame3.x + 0.5 * frame3.w);  // at the left
  CHECK(legend3.y + legend3.h <= frame3.y + frame3.h);

  // A point in every corner: inside, the legend would hide one; it goes under the panel's
  // axis title, and the figure grows by its height.
  const std::string four =
      report::svg_of(figure_with({0.03, 0.97, 0.97, 0.03}, {0.03, 0.03, 0.97, 0.97}));
  const Box frame4 = plot_frame(four), legend4 = legend_box(four);
  CHECK(legend4.y > frame4.y + frame4.h + 40);  // below the tick labels and the axis title
  CHECK(svg_height(four) >= legend4.y + legend4.h);
  CHECK(svg_height(four) > svg_height(three) + legend4.h);
}
