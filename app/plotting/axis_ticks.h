#pragma once
// Axis ranges and tick marks a reader can take in at a glance: round numbers 1, 2, 5 x 10^k on
// linear axes; decades, or 1-2-5 and 1..9 within them, on logarithmic axes. The one tick rule of
// the report's SVG figures and of the app's plots.

#include <string>
#include <vector>

namespace swarmlab::plotting {

struct AxisRange {
  double lo = 0, hi = 1;
};

struct AxisTicks {
  std::vector<double> values;  ///< ascending, inside the range
  std::vector<std::string> labels;
  /// A common power of ten taken out of the labels, e.g. "×10⁻¹³", to append to the axis label.
  std::string scale_suffix;
};

/// The tick count the report's figures are drawn with.
inline constexpr int kDefaultTickTarget = 6;

/// The data range [lo, hi] with a small margin (in log space on a log axis), never empty.
/// On a log axis lo must be > 0.
AxisRange padded_range(double lo, double hi, bool log, bool include_zero);

/// Ticks inside range for an axis with room for about `target` of them. Linear: multiples of
/// a step of 1, 2 or 5 x 10^k near (hi - lo) / target, which gives 0.6 target to 1.5 target + 1
/// ticks. Log: at least four labelled ticks: over less than a decade linear ticks as above,
/// asking for more if fewer than four come; else decades if at least four lie in the range,
/// else 1, 2 and 5 in each decade, else every digit (or 1, 2, 3 and 5 where the digits do not
/// fit), thinned to about 1.5 target + 1.
/// Ranges given backwards are read forwards; an empty range gives one tick, a range with an
/// infinite or NaN end none, a log range reaching zero or below the positive ones of its linear
/// ticks.
AxisTicks ticks_for(const AxisRange& range, bool log, int target = kDefaultTickTarget);

/// "⁻¹³" for -13: exponents written the way a printed page writes them.
std::string superscript(int n);

}  // namespace swarmlab::plotting
