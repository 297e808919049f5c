#include "axis_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace swarmlab::plotting {
namespace {

/// A log axis shows at least this many labelled ticks, so that a reader can tell its scale.
constexpr std::size_t kFewestLogTicks = 4;

/// 1, 2 or 5 times a power of ten, close to raw.
double nice_step(double raw) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / magnitude;
  return (f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10) * magnitude;
}

/// Ticks on a linear scale: multiples of one step, which sets how many decimals they need.
struct LinearTicks {
  std::vector<double> values;
  double step = 0;  ///< 0 for the lone tick of an empty range
};

/// Multiples of step inside [lo, hi]; with `positive`, only those above zero.
std::vector<double> multiples_of(double step, double lo, double hi, bool positive) {
  std::vector<double> values;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1)
    if (!positive || k > 0) values.push_back(k * step == 0 ? 0.0 : k * step);  // no "-0"
  return values;
}

/// Multiples of a nice step near (hi - lo) / target inside [lo, hi], for finite lo <= hi; with
/// `positive` (a log axis reaching zero), only those above zero. At least two on a range with
/// width (ticks_for says how).
LinearTicks linear_ticks(double lo, double hi, int target, bool positive = false) {
  if (!(hi > lo)) return positive && lo <= 0 ? LinearTicks{} : LinearTicks{{lo}, 0};
  if (!std::isfinite(hi - lo) || (positive && hi <= 0)) return {};
  const double first_step = nice_step((hi - lo) / target);
  if (positive) lo = std::max(lo, 0.0);  // no need to count the steps below zero
  for (double step = first_step;; step = nice_step(0.5 * step)) {  // 5 -> 2 -> 1 -> 0.5
    // Past 2^50 steps from zero, doubles cannot count steps any more: show the two ends.
    if (std::max(std::abs(lo), std::abs(hi)) / step > 1e15) return {{lo, hi}, hi - lo};
    std::vector<double> values = multiples_of(step, lo, hi, positive);
    if (values.size() < 2) continue;
    // A step finer than the room asked for: only its outermost two, which fit the room.
    if (step != first_step) values = {values.front(), values.back()};
    return {std::move(values), step};
  }
}

/// The most ticks the linear rule gives for a target, and so the most any axis should get.
std::size_t most_ticks(int target) { return std::size_t(1.5 * target) + 1; }

/// Every stride-th value, so that about 1.5 target + 1 remain (what the linear rule gives at
/// most), but never fewer than four.
std::vector<double> thinned(const std::vector<double>& values, int target) {
  const std::size_t most = most_ticks(target);
  const std::size_t stride = std::max<std::size_t>(
      1, std::min((values.size() + most - 1) / most, values.size() / kFewestLogTicks));
  std::vector<double> out;
  for (std::size_t i = 0; i < values.size(); i += stride) out.push_back(values[i]);
  return out;
}

std::string printed(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

/// Decimals enough to tell ticks `step` apart.
int decimals_for(double step) { return std::max(0, int(std::ceil(-std::log10(step) - 1e-9))); }

AxisTicks linear_labels(LinearTicks ticks) {
  AxisTicks t;
  t.values = std::move(ticks.values);
  // A lone tick (an empty range) has no step to round to: all its digits that matter.
  if (t.values.size() < 2) {
    for (double v : t.values) t.labels.push_back(printed("%g", v));
    return t;
  }
  double largest = 0;
  for (double v : t.values) largest = std::max(largest, std::abs(v));
  const double step = ticks.step;
  // Very large or very small numbers: a common power of ten goes to the axis label.
  const int exponent = largest > 0 ? int(std::floor(std::log10(largest))) : 0;
  const double scale = (exponent >= 5 || exponent <= -4) ? std::pow(10.0, exponent) : 1.0;
  if (scale != 1.0) t.scale_suffix = "×10" + superscript(exponent);
  const std::string format = "%." + std::to_string(decimals_for(step / scale)) + "f";
  for (double v : t.values) t.labels.push_back(printed(format.c_str(), v / scale));
  return t;
}

std::string log_label(double v) {
  const int exponent = int(std::floor(std::log10(v) + 1e-9));
  if (exponent >= -3 && exponent <= 4) return printed("%g", v);
  const double mantissa = v / std::pow(10.0, exponent);
  const std::string power = "10" + superscript(exponent);
  return std::abs(mantissa - 1) < 1e-9 ? power : printed("%g", mantissa) + "×" + power;
}

/// A log axis over less than a decade: round linear values read better than a few digits of
/// one decade. The linear rule gives at least 0.6 target ticks, so if fewer than four come,
/// twice and then four times as many are asked for, until the target is at least seven.
AxisTicks less_than_a_decade(double lo, double hi, int target) {
  LinearTicks ticks;
  for (int wanted = target;; wanted *= 2) {
    ticks = linear_ticks(lo, hi, wanted);
    if (ticks.values.size() >= kFewestLogTicks || wanted >= 7) break;
  }
  return linear_labels(std::move(ticks));
}

}  // namespace

std::string superscript(int n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = n < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(n))) out += digits[c - '0'];
  return out;
}

AxisRange axis_range(double lo, double hi, const RangeOptions& options) {
  const bool log = options.log;
  if (!(lo <= hi)) lo = log ? 1 : 0, hi = log ? 10 : 1;
  if (options.min) lo = *options.min;
  if (options.max) hi = *options.max;
  // A fixed end beyond all the data: the free end joins it.
  if (lo > hi) {
    if (options.min)
      hi = lo;
    else
      lo = hi;
  }
  if (options.include_zero && !log) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
  // Ends that take no margin: the caller's, and a zero that the data start from.
  const bool low_fixed =
      options.min || (options.include_zero && options.zero_on_frame && !log && lo == 0);
  const bool high_fixed = options.max.has_value();

  double a = log ? std::log10(lo) : lo, b = log ? std::log10(hi) : hi;
  // One value to twelve digits, measured against the values themselves (as a difference of
  // logarithms already is).
  const double tolerance = log ? 1e-12 : 1e-300 + 1e-12 * std::max(std::abs(a), std::abs(b));
  const bool one_value = b - a <= tolerance;
  if (one_value) {
    const double half = log ? 0.5 * options.one_value_decades : a != 0 ? 0.1 * std::abs(a) : 1.0;
    if (low_fixed || (options.one_value == OneValue::at_start && !log))
      b = a + 2 * half;
    else if (high_fixed)
      a = b - 2 * half;
    else
      a -= half, b += half;
  }
  if (!one_value || options.margin_around_one_value) {
    const double pad = options.margin * (b - a);
    if (!low_fixed) a -= pad;
    if (!high_fixed) b += pad;
  }
  return log ? AxisRange{std::pow(10.0, a), std::pow(10.0, b)} : AxisRange{a, b};
}

AxisTicks ticks_for(const AxisRange& range, bool log, int target) {
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi)) return {};
  const double lo = std::min(range.lo, range.hi), hi = std::max(range.lo, range.hi);
  target = std::max(target, 1);
  if (!log) return linear_labels(linear_ticks(lo, hi, target));
  // Ticks at or below zero cannot sit on a log axis.
  if (lo <= 0) return linear_labels(linear_ticks(lo, hi, target, true));
  if (hi < 10 * lo) return less_than_a_decade(lo, hi, target);

  // Decades if there are enough of them, else 1-2-5, else every digit (a decade holds nine):
  // whichever first gives at least four ticks. Digits too many for the room give way to 1, 2,
  // 3 and 5 if those are four, before every stride-th is taken.
  const int first = int(std::floor(std::log10(lo)));
  const int last = int(std::ceil(std::log10(hi)));
  auto ticks_with = [&](std::initializer_list<double> mantissas) {
    std::vector<double> values;
    for (int e = first; e <= last; ++e)
      for (double m : mantissas) {
        const double v = m * std::pow(10.0, e);
        if (std::isfinite(v) && v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12)) values.push_back(v);
      }
    return values;
  };
  std::vector<double> values = ticks_with({1});
  if (values.size() < kFewestLogTicks) values = ticks_with({1, 2, 5});
  if (values.size() < kFewestLogTicks) {
    values = ticks_with({1, 2, 3, 4, 5, 6, 7, 8, 9});
    const std::vector<double> fewer = ticks_with({1, 2, 3, 5});
    if (values.size() > most_ticks(target) && fewer.size() >= kFewestLogTicks) values = fewer;
  }
  AxisTicks t;
  t.values = thinned(values, target);
  for (double v : t.values) t.labels.push_back(log_label(v));
  return t;
}

double tick_position(double value, const AxisRange& range, bool log, double length) {
  const double lo = std::min(range.lo, range.hi), hi = std::max(range.lo, range.hi);
  if (log && lo > 0 && value > 0)
    return length * (std::log10(value) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
  return hi > lo ? length * (value - lo) / (hi - lo) : 0;
}

namespace {

/// Whether each label's box, centred on its tick, keeps the gap to the next one's.
bool labels_fit(const AxisTicks& t, const AxisRange& range, bool log, const AxisRoom& room) {
  for (std::size_t i = 0; i + 1 < t.values.size(); ++i) {
    const double a = tick_position(t.values[i], range, log, room.length);
    const double b = tick_position(t.values[i + 1], range, log, room.length);
    const double half_widths = 0.5 * (room.label_length(t.labels[i], room.context) +
                                      room.label_length(t.labels[i + 1], room.context));
    if (std::abs(b - a) < half_widths + room.gap) return false;
  }
  return true;
}

}  // namespace

AxisTicks ticks_that_fit(const AxisRange& range, bool log, const AxisRoom& room) {
  // No label is shorter than one digit: the length holds no more ticks than such labels.
  const double shortest = room.label_length("0", room.context) + room.gap;
  AxisTicks t;
  for (int target = std::max(1, int(room.length / std::max(shortest, 1.0))); target >= 1;
       target = target > 12 ? target * 2 / 3 : target - 1) {
    t = ticks_for(range, log, target);
    if (labels_fit(t, range, log, room)) return t;
  }
  // Even the fewest do not fit: keep every stride-th tick (with its label) until they do.
  for (std::size_t stride = 2; t.values.size() / stride >= 1; ++stride) {
    AxisTicks kept;
    kept.scale_suffix = t.scale_suffix;
    for (std::size_t i = 0; i < t.values.size(); i += stride) {
      kept.values.push_back(t.values[i]);
      kept.labels.push_back(t.labels[i]);
    }
    if (labels_fit(kept, range, log, room)) return kept;
    if (kept.values.size() <= 1) return kept;
  }
  return t;
}

}  // namespace swarmlab::plotting
