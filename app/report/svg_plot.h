#pragma once
// Draws a Figure as a self-contained SVG document: title, panels with frames, grid, ticks,
// tick labels, axis labels with units, legends placed where the data is not, and lines,
// points, dashed lines and zero lines. No fonts or scripts are embedded. What made the figure
// (Figure::made_by) goes into a <metadata> element, one line each, escaped for XML.

#include <string>

#include "figure.h"

namespace swarmlab::report {

std::string svg_of(const Figure& figure);

}  // namespace swarmlab::report
