#pragma once
// The report figure of an app plot (report/figure.h), for its SVG and CSV export: one panel
// with the plot's series and fit lines, each in the colour it has on screen, on the theme's
// background with its text and grid colours, so that the SVG looks as the plot does. Pure (no
// ImGui), tested in tests/ui/plots/.

#include "access/theme_palette.h"
#include "report/figure.h"
#include "ui/plots/plot_spec.h"

namespace swarmlab {

/// "#rrggbb" of a colour (its alpha goes to an opacity).
std::string css_rgb(const Colour& c);

/// The figure of a plot drawn in a theme's palette (its series carry their own colours).
report::Figure figure_of(const PlotSpec& spec, const Palette& palette);

}  // namespace swarmlab
