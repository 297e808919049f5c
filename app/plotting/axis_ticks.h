#pragma once
// Axis ranges and tick marks a reader can take in at a glance: round numbers 1, 2, 5 x 10^k on
// linear axes; decades, or 1-2-5 and 1..9 within them, on logarithmic axes. The one tick rule of
// the report's SVG figures and of the app's plots.

#include <optional>
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

/// Where data at one value (a constant, a first sample) sit on the axis opened up around them.
enum class OneValue {
  centred,   ///< in the middle: a value axis
  at_start,  ///< at the low end of a linear axis, with room for the run to come: a time axis
};

/// How axis_range makes an axis range from the data's extent. The defaults are the report
/// figures'; the app's plots (ui/plots/plot_widget.cpp) keep zero and a lone value on the frame.
struct RangeOptions {
  bool log = false;
  /// Stretch a linear range to hold 0 (a pressure, a temperature).
  bool include_zero = false;
  /// With include_zero: data that never go below 0 start at 0 on the frame, as if the minimum
  /// were pinned there, rather than with a margin under it.
  bool zero_on_frame = false;
  /// Ends the caller fixes (a scroll window, a histogram's bins): kept exactly, with no margin.
  std::optional<double> min, max;
  OneValue one_value = OneValue::centred;
  /// The margin at each free end, as a fraction of the range (of its logarithm on a log axis),
  /// so that the curve stays off the frame.
  double margin = 0.04;
  /// How wide a log axis over one value is opened, in decades. A linear one is opened to a
  /// fifth of the value (2 at zero): never so narrow that its ticks read "×10⁻⁹".
  double one_value_decades = 0.2;
  /// Whether the margin goes around an axis opened up over one value too, or the opened width
  /// is the whole range.
  bool margin_around_one_value = true;
};

/// The axis range of data in [lo, hi] (on a log axis lo > 0), never empty. Data at one value,
/// to twelve digits (a spread of 1e-15 about 1e-15 is data to show, a spread of 1e-15 about 1
/// is not), are opened up as the options say. No data (lo > hi, or NaN) stand in as 0 to 1, or
/// 1 to 10 on a log axis, so that an empty plot still has axes. A fixed end the data cannot
/// reach drags the free end to it.
AxisRange axis_range(double lo, double hi, const RangeOptions& options = {});

/// Ticks inside range for an axis with room for about `target` of them. Linear: multiples of
/// a step of 1, 2 or 5 x 10^k near (hi - lo) / target, which gives 0.6 target to 1.5 target + 1
/// ticks. Never a lone tick on a range with width, since one label cannot tell the axis's
/// scale: where the step leaves fewer than two (a target below four), the next finer 1-2-5
/// steps are tried until two fit, and the outermost two of those are kept, so the labels stay
/// round, as far apart as the range allows, and no more than the room asked for.
/// Log: at least four labelled ticks: over less than a decade linear ticks as above, asking
/// for more if fewer than four come; else decades if at least four lie in the range, else 1, 2
/// and 5 in each decade, else every digit (or 1, 2, 3 and 5 where the digits do not fit),
/// thinned to about 1.5 target + 1.
/// Ranges given backwards are read forwards; an empty range gives one tick (it has no scale to
/// tell), a range with an infinite or NaN end none, a log range reaching zero or below the
/// positive ones of its linear ticks, at least two where it reaches above zero.
AxisTicks ticks_for(const AxisRange& range, bool log, int target = kDefaultTickTarget);

/// An axis on screen: how long it is and how much room one label takes along it.
struct AxisRoom {
  double length = 0;  ///< pixels from the range's low end to its high end
  /// Pixels a label takes along the axis: its width on an x axis, its height on a y axis.
  double (*label_length)(const std::string& label, const void* context) = nullptr;
  const void* context = nullptr;
  double gap = 0;  ///< pixels kept free between two labels
};

/// Where a tick of `range` lies along an axis `length` pixels long, from the low end.
double tick_position(double value, const AxisRange& range, bool log, double length);

/// The ticks of ticks_for with as many as the room holds without two labels' boxes (with the
/// gap between them) overlapping: the target falls from what the length could hold until
/// they fit, and where even the fewest the rule gives do not (a log axis keeps four), every
/// second, third, ... tick is kept, down to one. Never labels that overlap.
AxisTicks ticks_that_fit(const AxisRange& range, bool log, const AxisRoom& room);

/// "⁻¹³" for -13: exponents written the way a printed page writes them.
std::string superscript(int n);

}  // namespace swarmlab::plotting
