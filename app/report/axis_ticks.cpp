#include "axis_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace swarmlab::report {
namespace {

/// 1, 2 or 5 times a power of ten, close to raw.
double nice_step(double raw) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / magnitude;
  return (f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10) * magnitude;
}

std::vector<double> linear_ticks(double lo, double hi) {
  const double step = nice_step((hi - lo) / 6);
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1)
    ticks.push_back(k * step == 0 ? 0.0 : k * step);  // no "-0"
  return ticks;
}

std::string printed(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

/// Decimals enough to tell ticks `step` apart.
int decimals_for(double step) { return std::max(0, int(std::ceil(-std::log10(step) - 1e-9))); }

AxisTicks linear_labels(std::vector<double> values) {
  AxisTicks t;
  t.values = std::move(values);
  double largest = 0;
  for (double v : t.values) largest = std::max(largest, std::abs(v));
  const double step = t.values.size() > 1 ? t.values[1] - t.values[0] : std::max(largest, 1.0);
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

/// Ticks at or below zero cannot sit on a log axis.
AxisTicks positive_only(AxisTicks t) {
  for (std::size_t i = t.values.size(); i-- > 0;)
    if (t.values[i] <= 0) {
      t.values.erase(t.values.begin() + long(i));
      t.labels.erase(t.labels.begin() + long(i));
    }
  return t;
}

}  // namespace

std::string superscript(int n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = n < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(n))) out += digits[c - '0'];
  return out;
}

AxisRange padded_range(double lo, double hi, bool log, bool include_zero) {
  if (log) {
    double a = std::log10(lo), b = std::log10(hi);
    if (b - a < 1e-12) a -= 0.1, b += 0.1;
    const double pad = 0.04 * (b - a);
    return {std::pow(10.0, a - pad), std::pow(10.0, b + pad)};
  }
  if (include_zero) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
  if (hi - lo <= 1e-300 + 1e-12 * std::abs(hi)) {
    const double half = lo != 0 ? 0.1 * std::abs(lo) : 1.0;
    lo -= half, hi += half;
  }
  const double pad = 0.04 * (hi - lo);
  return {lo - pad, hi + pad};
}

AxisTicks ticks_for(const AxisRange& range, bool log) {
  if (!log) return linear_labels(linear_ticks(range.lo, range.hi));

  // Less than a decade: round linear values read better than a few digits of one decade.
  if (range.hi < 10 * range.lo)
    return positive_only(linear_labels(linear_ticks(range.lo, range.hi)));
  // Decades if there are enough of them, else 1-2-5, else every digit: whichever first gives
  // at least four ticks.
  const int first = int(std::floor(std::log10(range.lo)));
  const int last = int(std::ceil(std::log10(range.hi)));
  const std::vector<std::vector<double>> mantissa_sets = {
      {1}, {1, 2, 5}, {1, 2, 3, 4, 5, 6, 7, 8, 9}};
  for (const auto& mantissas : mantissa_sets) {
    std::vector<double> values;
    for (int e = first; e <= last; ++e)
      for (double m : mantissas) {
        const double v = m * std::pow(10.0, e);
        if (v >= range.lo * (1 - 1e-12) && v <= range.hi * (1 + 1e-12)) values.push_back(v);
      }
    if (values.size() >= 4) {
      // Many decades: every second or third, so the labels do not crowd.
      const std::size_t stride = (values.size() + 9) / 10;
      AxisTicks t;
      for (std::size_t i = 0; i < values.size(); i += stride) {
        t.values.push_back(values[i]);
        t.labels.push_back(log_label(values[i]));
      }
      return t;
    }
  }
  return positive_only(linear_labels(linear_ticks(range.lo, range.hi)));
}

}  // namespace swarmlab::report
