#pragma once
// The numbers behind a figure as CSV, so a reader can re-plot or check them.

#include <string>

#include "report/figure.h"

namespace swarmlab::report {

/// The figure's made_by lines first, each behind "# " (a reader skips them as comments), then
/// one row per drawn point: panel,series,x,y (every field quoted: report/csv_field.h), where
/// panel counts from 0 at the top, series is the legend name (or, for an unnamed series, the
/// panel's y axis) and the header names x. Eight significant digits: what the figure shows, in
/// files small enough to commit.
std::string csv_of(const Figure& figure);

}  // namespace swarmlab::report
