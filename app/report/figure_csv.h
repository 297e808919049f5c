#pragma once
// The numbers behind a figure as CSV, so a reader can re-plot or check them.

#include <string>

#include "figure.h"

namespace swarmlab::report {

/// One row per drawn point: panel,series,x,y. The header names the first panel's axes, and
/// each series keeps its legend name (or the panel's y label when it has none).
std::string csv_of(const Figure& figure);

}  // namespace swarmlab::report
