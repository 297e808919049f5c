#pragma once
// Axis ranges and tick marks a reader can take in at a glance: round numbers 1, 2, 5 x 10^k on
// linear axes; decades, or 1-2-5 and 1..9 within them, on logarithmic axes.

#include <string>
#include <vector>

namespace swarmlab::report {

struct AxisRange {
  double lo = 0, hi = 1;
};

struct AxisTicks {
  std::vector<double> values;
  std::vector<std::string> labels;
  /// A common power of ten taken out of the labels, e.g. "×10⁻¹³", to append to the axis label.
  std::string scale_suffix;
};

/// The data range [lo, hi] with a small margin (in log space on a log axis), never empty.
/// On a log axis lo must be > 0.
AxisRange padded_range(double lo, double hi, bool log, bool include_zero);

/// Four to a dozen ticks inside range.
AxisTicks ticks_for(const AxisRange& range, bool log);

/// "⁻¹³" for -13: exponents written the way a printed page writes them.
std::string superscript(int n);

}  // namespace swarmlab::report
