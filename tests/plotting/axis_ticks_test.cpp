#include "plotting/axis_ticks.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

using namespace swarmlab::plotting;

namespace {

/// The power of ten below v and v's mantissa in [1, 10).
double mantissa_of(double v) { return v / std::pow(10.0, std::floor(std::log10(v) + 1e-12)); }

/// The number 1, 2 or 5 times a power of ten nearest to step.
double nearest_one_two_five(double step) {
  const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-12));
  double best = power;
  for (double nice : {2.0, 5.0, 10.0})
    if (std::abs(step - nice * power) < std::abs(step - best)) best = nice * power;
  return best;
}

/// Within `tolerance` (a fraction) of 1, 2 or 5 times a power of ten.
bool is_one_two_five(double step, double tolerance = 1e-9) {
  return std::abs(step - nearest_one_two_five(step)) < tolerance * step;
}

bool is_whole(double v, double tolerance = 1e-6) { return std::abs(v - std::round(v)) < tolerance; }

/// How far, in steps, doubles may put a tick of a range that lies far from zero: a few units
/// in the last place of the range's largest end.
double rounding_in_steps(const AxisRange& r, double step) {
  return 1e-9 + 1e-15 * std::max(std::abs(r.lo), std::abs(r.hi)) / step;
}

/// Ranges of every sign, width and magnitude, from 1e-15 to 1e15 wide.
std::vector<AxisRange> linear_ranges() {
  std::vector<AxisRange> out;
  for (double centre : {0.0, 0.37, -2.9, 1234.5, -7.1e7, 4.4e-9})
    for (int e = -15; e <= 15; ++e)
      for (double m : {1.0, 1.37, 2.2, 2.95, 3.1, 4.9, 6.99, 7.3, 9.9}) {
        const double span = m * std::pow(10.0, e);
        if (std::abs(centre) > 1e10 * span) continue;  // past what a padded range ever holds
        for (double shift : {0.0, 0.31, 0.5, 0.77})
          out.push_back({centre - shift * span, centre + (1 - shift) * span});
      }
  return out;
}

/// Positive ranges from a factor 1.01 to 1e40 wide, at magnitudes from 1e-200 to 1e200.
std::vector<AxisRange> log_ranges() {
  std::vector<AxisRange> out;
  for (double lo : {1e-200, 3.3e-7, 0.051, 1.0, 4.7, 99.0, 2.2e12, 1e200})
    for (double factor : {1.01, 1.3,   2.0,   2.99, 3.0,   4.53, 7.0, 9.99, 10.0, 12.0, 31.0,
                          99.0, 450.0, 999.0, 1e3,  2.1e3, 1e4,  3e6, 1e9,  1e17, 1e40})
      if (lo * factor < 1e300) out.push_back({lo, lo * factor});
  return out;
}

/// The 1-2-5 step whose multiples the ticks are: the spacing of three or more, or for two (the
/// outermost of a finer step's ticks) the coarsest 1-2-5 step, at most four to the spacing,
/// that both are multiples of; 0 if there is none.
double grid_step(const std::vector<double>& values, double tolerance) {
  const double spacing = (values.back() - values.front()) / double(values.size() - 1);
  for (int k = 1; k <= (values.size() == 2 ? 4 : 1); ++k) {
    const double step = nearest_one_two_five(spacing / k);
    if (!is_one_two_five(spacing / k, tolerance)) continue;
    bool multiples = true;
    for (double v : values) multiples = multiples && is_whole(v / step, tolerance);
    if (multiples) return step;
  }
  return 0;
}

/// Labels are the values, up to a common power of ten that the suffix names.
void check_labels_match(const AxisTicks& t) {
  REQUIRE(t.labels.size() == t.values.size());
  if (t.values.size() < 2) return;
  // Find the scale from the suffix "×10ⁿ", or 1.
  int exponent = 0;
  if (!t.scale_suffix.empty()) {
    bool found = false;
    for (int n = -330; n <= 330 && !found; ++n)
      if (t.scale_suffix == "×10" + superscript(n)) exponent = n, found = true;
    REQUIRE(found);
  }
  const double scale = std::pow(10.0, exponent);
  const double step = (t.values.back() - t.values.front()) / double(t.values.size() - 1);
  const double tolerance = rounding_in_steps({t.values.front(), t.values.back()}, step);
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    CAPTURE(t.labels[i]);
    CHECK(std::abs(std::stod(t.labels[i]) * scale - t.values[i]) < tolerance * step);
    if (i > 0) CHECK(t.labels[i] != t.labels[i - 1]);
  }
}

}  // namespace

TEST_CASE("linear ticks are multiples of one 1-2-5 step that cover the range") {
  for (int target : {1, 2, 3, 4, 6, 11}) {
    for (const AxisRange& r : linear_ranges()) {
      CAPTURE(target);
      CAPTURE(r.lo);
      CAPTURE(r.hi);
      const AxisTicks t = ticks_for(r, false, target);
      // About target ticks: at least 0.6 target (a step of 5 where 3 was asked), at most
      // 1.5 target + 1 (a step of 1 where 1.5 was asked); and never one alone.
      REQUIRE(t.values.size() >= 2);
      CHECK(t.values.size() >= std::size_t(0.6 * target));
      CHECK(t.values.size() <= std::size_t(1.5 * target) + 1);
      const double spacing = (t.values.back() - t.values.front()) / double(t.values.size() - 1);
      const double tolerance = rounding_in_steps(r, spacing);
      // Multiples of the exact step: a step measured between ticks far from zero is blurred.
      const double step = grid_step(t.values, tolerance);
      REQUIRE(step > 0);
      // Where the room's step gives two or more, the ticks are its every multiple.
      if (target >= 4) CHECK(std::abs(spacing - step) < tolerance * step);
      for (std::size_t i = 0; i < t.values.size(); ++i) {
        CHECK(t.values[i] >= r.lo - tolerance * step);
        CHECK(t.values[i] <= r.hi + tolerance * step);
        if (i > 0) CHECK(std::abs(t.values[i] - t.values[i - 1] - spacing) < tolerance * step);
      }
      // Covered: no gap of a whole step between an end of the range and the nearest tick.
      CHECK(t.values.front() - r.lo < step * (1 + tolerance));
      CHECK(r.hi - t.values.back() < step * (1 + tolerance));
      check_labels_match(t);
    }
  }
}

TEST_CASE("a lone tick never hides an axis's scale: two round labelled ticks on any width") {
  // Room for two labels (a short residual plot) and a step of 5 that leaves only 0 inside:
  // the step of 2 would give five labels, so its outermost two are kept.
  const AxisTicks around_zero = ticks_for({-4.95, 4.95}, false, 2);
  CHECK(around_zero.values == std::vector<double>{-4, 4});
  CHECK(around_zero.labels == std::vector<std::string>{"-4", "4"});
  // A step of 10 leaves 10 alone; the step of 5 gives 5 and 10.
  CHECK(ticks_for({0.5, 14.5}, false, 2).labels == std::vector<std::string>{"5", "10"});
  // The finer step (0.5, after 2 and 1 left only 0) sets the decimals, not the distance of 1
  // between the two, which would print them "-0" and "0".
  CHECK(ticks_for({-0.9, 0.9}, false, 1).labels == std::vector<std::string>{"-0.5", "0.5"});
  // A log axis reaching below zero keeps two of its positive ticks.
  CHECK(ticks_for({-5, 3}, true, 2).labels == std::vector<std::string>{"1", "3"});
  // Tiny values keep their power of ten in the suffix.
  const AxisTicks tiny = ticks_for({-4.95e-9, 4.95e-9}, false, 2);
  CHECK(tiny.labels == std::vector<std::string>{"-4", "4"});
  CHECK(tiny.scale_suffix == "×10⁻⁹");
  // Log axes: at least four wherever they lie, however little room (tested above for
  // targets 2 to 11), so none within one decade stands alone either.
  for (int target : {1, 2, 3})
    for (const AxisRange& r : log_ranges()) {
      CAPTURE(target);
      CAPTURE(r.lo);
      CAPTURE(r.hi);
      CHECK(ticks_for(r, true, target).values.size() >= 4);
    }
  // Log ranges that reach zero or below: two positive ticks wherever the range goes above 0.
  for (int target : {1, 2, 6})
    for (double lo : {-1e6, -5.0, -0.3, 0.0})
      for (double hi : {1e-7, 0.4, 3.0, 17.0, 2e5}) {
        CAPTURE(target);
        CAPTURE(lo);
        CAPTURE(hi);
        const AxisTicks t = ticks_for({lo, hi}, true, target);
        CHECK(t.values.size() >= 2);
        for (double v : t.values) CHECK(v > 0);
        check_labels_match(t);
      }
}

TEST_CASE("the report's figures get four to ten ticks on every linear axis they pad") {
  for (double lo : {-3.0, 0.0, 0.2, 17.0, 1e-13, 6.02e23})
    for (double hi : {0.5, 1.0, 2.9, 40.0, 1e5, 7e23}) {
      if (hi <= lo) continue;
      const AxisTicks t = ticks_for(axis_range(lo, hi), false);
      CAPTURE(lo);
      CAPTURE(hi);
      CHECK(t.values.size() >= 3);
      CHECK(t.values.size() <= 10);
    }
}

TEST_CASE("tick labels: fixed decimals, and a power of ten taken out of tiny or huge values") {
  const AxisTicks unit = ticks_for({0, 1}, false);
  CHECK(unit.labels == std::vector<std::string>{"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"});
  CHECK(unit.scale_suffix.empty());
  const AxisTicks tiny = ticks_for({0, 3e-13}, false);
  CHECK(tiny.scale_suffix == "×10⁻¹³");
  CHECK(tiny.labels.front() == "0.0");
  CHECK(tiny.labels[1] == "0.5");
  const AxisTicks big = ticks_for({-2e6, 4e6}, false);
  CHECK(big.scale_suffix == "×10⁶");
  CHECK(big.labels.front() == "-2");
  CHECK(superscript(-13) == "⁻¹³");
  CHECK(superscript(0) == "⁰");
  CHECK(superscript(2048) == "²⁰⁴⁸");
}

TEST_CASE("log ticks: decades, else 1-2-5 or every digit within decades, at least four") {
  for (int target : {2, 4, 6, 11})
    for (const AxisRange& r : log_ranges()) {
      CAPTURE(target);
      CAPTURE(r.lo);
      CAPTURE(r.hi);
      const AxisTicks t = ticks_for(r, true, target);
      REQUIRE(t.labels.size() == t.values.size());
      CHECK(t.values.size() >= 4);
      for (std::size_t i = 0; i < t.values.size(); ++i) {
        CHECK(t.values[i] >= r.lo * (1 - 1e-9));
        CHECK(t.values[i] <= r.hi * (1 + 1e-9));
        if (i > 0) CHECK(t.values[i] > t.values[i - 1]);
      }
      if (r.hi < 10 * r.lo) {
        // Less than a decade: linear multiples of one 1-2-5 step.
        const double step = t.values[1] - t.values[0];
        CHECK(is_one_two_five(step));
        for (double v : t.values) CHECK(is_whole(v / nearest_one_two_five(step)));
        check_labels_match(t);
        continue;
      }
      // Thinned by a whole stride to about 1.5 target + 1, but to no fewer than four, which
      // can leave up to seven.
      CHECK(t.values.size() <= std::max<std::size_t>(7, std::size_t(1.5 * target) + 1));
      // The powers of ten in the range decide: four or more give decades only.
      int decades = 0;
      for (int e = -330; e <= 330; ++e) {
        const double p = std::pow(10.0, e);
        if (p >= r.lo * (1 - 1e-12) && p <= r.hi * (1 + 1e-12)) ++decades;
      }
      for (double v : t.values) {
        const double m = mantissa_of(v);
        CAPTURE(v);
        CHECK(is_whole(m));
        if (decades >= 4) CHECK(std::abs(m - 1) < 1e-9);
      }
      // Decades leave no gap of more than a factor 10^stride; digits and 1-2-5 no more than
      // a factor ten, so the range is covered.
      const double widest = decades >= 4 ? std::pow(10.0, std::ceil(decades / 4.0)) : 10.0;
      CHECK(t.values.front() <= r.lo * widest);
      CHECK(t.values.back() >= r.hi / widest);
    }
}

TEST_CASE("a log axis over a factor of about three or more shows four labelled ticks") {
  // The cases where a single step of 5 over a short axis would give three ticks.
  for (const AxisRange r : {AxisRange{5.1, 23.1}, AxisRange{0.51, 2.31}, AxisRange{3, 9.1}}) {
    const AxisTicks t = ticks_for(r, true);
    CAPTURE(r.lo);
    CHECK(t.values.size() >= 4);
    CHECK(t.labels.size() == t.values.size());
  }
  // A few decades get 1, 2 and 5 in each, labelled as a printed page writes them.
  const AxisTicks few = ticks_for({0.9, 900}, true);
  CHECK(few.labels ==
        std::vector<std::string>{"1", "2", "5", "10", "20", "50", "100", "200", "500"});
  const AxisTicks small = ticks_for({2e-7, 3e-5}, true);
  CHECK(small.labels ==
        std::vector<std::string>{"2×10⁻⁷", "5×10⁻⁷", "10⁻⁶", "2×10⁻⁶", "5×10⁻⁶", "10⁻⁵", "2×10⁻⁵"});
  // About one decade: every digit where there is room, else 1, 2, 3 and 5.
  const AxisRange decade{std::pow(10.0, -0.5), std::pow(10.0, 0.5)};
  CHECK(ticks_for(decade, true).labels ==
        std::vector<std::string>{"0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1", "2", "3"});
  CHECK(ticks_for(decade, true, 2).labels == std::vector<std::string>{"0.5", "1", "2", "3"});
  // Thirty decades: every fourth.
  const AxisTicks many = ticks_for({1, 1e30}, true);
  CHECK(many.values.size() == 8);
  CHECK(many.labels.front() == "1");
  CHECK(many.labels[1] == "10000");
  CHECK(many.labels[2] == "10⁸");
}

TEST_CASE("degenerate ranges give a sane answer at once") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto started = std::chrono::steady_clock::now();
  for (bool log : {false, true}) {
    CAPTURE(log);
    // An empty range: one tick at its value, labelled with its digits.
    const AxisTicks one = ticks_for({2.5, 2.5}, log);
    CHECK(one.values == std::vector<double>{2.5});
    CHECK(one.labels == std::vector<std::string>{"2.5"});
    // Backwards: the same ticks as forwards.
    CHECK(ticks_for({8, 1}, log).values == ticks_for({1, 8}, log).values);
    // No finite range, no ticks.
    for (const AxisRange r : {AxisRange{nan, 1}, AxisRange{0, nan}, AxisRange{nan, nan},
                              AxisRange{0, inf}, AxisRange{-inf, inf}})
      CHECK(ticks_for(r, log).values.empty());
    // Wider than a double can subtract, or narrower than it can step.
    CHECK(ticks_for({-1.7e308, 1.7e308}, log).values.size() <= 11);
    const AxisTicks narrow = ticks_for({1e17, 1e17 + 64}, log);
    CHECK(narrow.values.size() >= 1);
    CHECK(narrow.values.size() <= 11);
  }
  CHECK(ticks_for({0, 0}, false).values == std::vector<double>{0.0});
  // Zero or below on a log axis: only positive ticks, or none.
  for (double v : ticks_for({0, 100}, true).values) CHECK(v > 0);
  for (double v : ticks_for({-5, 3}, true).values) CHECK(v > 0);
  CHECK(ticks_for({-5, -1}, true).values.empty());
  CHECK(ticks_for({0, 0}, true).values.empty());
  // A target of zero or below is read as one.
  CHECK(ticks_for({0, 1}, false, 0).values == ticks_for({0, 1}, false, 1).values);
  CHECK(std::chrono::steady_clock::now() - started < std::chrono::seconds(1));
}

TEST_CASE("axis ranges hold the data with a margin and are never empty") {
  for (bool include_zero : {false, true})
    for (double lo : {-4.0, 0.0, 1e-9, 3.0})
      for (double width : {0.0, 1e-20, 0.5, 1e6}) {
        const double hi = lo + width;
        RangeOptions options;
        options.include_zero = include_zero;
        const AxisRange r = axis_range(lo, hi, options);
        CHECK(r.lo < lo);
        CHECK(r.hi > hi);
        if (include_zero) CHECK(r.lo < 0);
        if (include_zero) CHECK(r.hi > 0);
      }
  RangeOptions log;
  log.log = true;
  for (double lo : {1e-12, 0.5, 7.0, 1e40})
    for (double factor : {1.0, 1.0 + 1e-14, 2.0, 1e6}) {
      const AxisRange r = axis_range(lo, lo * factor, log);
      CHECK(r.lo < lo);
      CHECK(r.hi > lo * factor);
      CHECK(r.lo > 0);
      // The margin on a log axis is a factor, the same at both ends.
      CHECK(lo / r.lo == doctest::Approx(r.hi / (lo * factor)).epsilon(1e-9));
    }
}

namespace {

/// The range, against one worked out by hand.
void check_range(const AxisRange& r, double lo, double hi) {
  CHECK(r.lo == doctest::Approx(lo).epsilon(1e-12));
  CHECK(r.hi == doctest::Approx(hi).epsilon(1e-12));
}

}  // namespace

TEST_CASE("axis_range as the figures use it: 4 % margins, one value opened by a tenth") {
  check_range(axis_range(0, 10), -0.4, 10.4);
  RangeOptions zero;
  zero.include_zero = true;
  check_range(axis_range(2, 10, zero), -0.4, 10.4);  // 0 with a margin under it
  check_range(axis_range(-10, -2, zero), -10.4, 0.4);
  // One value: 5 opened to 4.5..5.5, then 4 % of that each side; at zero, to -1..1.
  check_range(axis_range(5, 5), 4.46, 5.54);
  check_range(axis_range(-5, -5), -5.54, -4.46);
  check_range(axis_range(0, 0), -1.08, 1.08);
  // One value to twelve digits: a spread of 1e-15 about 1 is not data, about 1e-15 it is.
  check_range(axis_range(1, 1 + 1e-15), 0.892, 1.108);
  check_range(axis_range(1e-15, 2e-15), 0.96e-15, 2.04e-15);
  // No data: 0 to 1, or 1 to 10 on a log axis, so that the axes can still be drawn.
  const double inf = std::numeric_limits<double>::infinity();
  check_range(axis_range(inf, -inf), -0.04, 1.04);
  RangeOptions log;
  log.log = true;
  check_range(axis_range(inf, -inf, log), std::pow(10.0, -0.04), std::pow(10.0, 1.04));
  // Log axes: the margin and the opening in decades. 1 to 100 is two decades, 0.08 each side.
  check_range(axis_range(1, 100, log), std::pow(10.0, -0.08), std::pow(10.0, 2.08));
  check_range(axis_range(10, 10, log), std::pow(10.0, 0.892), std::pow(10.0, 1.108));
  // include_zero means nothing on a log axis.
  log.include_zero = true;
  check_range(axis_range(1, 100, log), std::pow(10.0, -0.08), std::pow(10.0, 2.08));
}

TEST_CASE("axis_range as the app's plots use it: zero, fixed ends and one value on the frame") {
  // The options of ui/plots/plot_widget.cpp.
  auto live = [](OneValue one_value, bool from_zero = false, bool log = false) {
    RangeOptions o;
    o.log = log;
    o.include_zero = from_zero;
    o.zero_on_frame = true;
    o.one_value = one_value;
    o.margin = 0.05;
    o.one_value_decades = 1;
    o.margin_around_one_value = false;
    return o;
  };
  // A time axis with one sample: at the left edge, a fifth of its value (2 at zero) ahead.
  check_range(axis_range(0, 0, live(OneValue::at_start)), 0, 2);
  check_range(axis_range(3, 3, live(OneValue::at_start)), 3, 3.6);
  check_range(axis_range(0, 10, live(OneValue::at_start)), -0.5, 10.5);
  // A value axis with one value: centred, a fifth of it wide, no margin beyond that.
  check_range(axis_range(4, 4, live(OneValue::centred)), 3.6, 4.4);
  // From zero: data never below 0 start at 0 on the frame, with the margin above only...
  check_range(axis_range(2, 10, live(OneValue::centred, true)), 0, 10.5);
  // ...and all at zero (no pressure yet) opens upward, not to -1..1.
  check_range(axis_range(0, 0, live(OneValue::centred, true)), 0, 2);
  // Data below zero keep their margin; the 0 they reach up to gets one too.
  check_range(axis_range(-10, -2, live(OneValue::centred, true)), -10.5, 0.5);
  // A pinned minimum (the scroll window's start) takes no margin; the free end does.
  RangeOptions window = live(OneValue::at_start);
  window.min = 10;
  check_range(axis_range(8, 20, window), 10, 20.5);
  // Both ends pinned (a histogram's bins): exactly those.
  RangeOptions bins = live(OneValue::centred, true);
  bins.min = 0;
  bins.max = 4;
  check_range(axis_range(0.3, 3.1, bins), 0, 4);
  // A minimum beyond all the data: the other end joins it, and a fifth is opened above.
  window.min = 30;
  check_range(axis_range(8, 20, window), 30, 36);
  // A pinned maximum with one value: opened downward, the maximum kept.
  RangeOptions top = live(OneValue::centred);
  top.max = 5;
  check_range(axis_range(5, 5, top), 4, 5);
  // Log axes: a decade around one value (a first stage), 5 % of the decades as margin.
  check_range(axis_range(100, 100, live(OneValue::centred, false, true)), std::pow(10.0, 1.5),
              std::pow(10.0, 2.5));
  check_range(axis_range(1, 1000, live(OneValue::at_start, false, true)), std::pow(10.0, -0.15),
              std::pow(10.0, 3.15));
}

namespace {

/// A label's extent along the axis in pixels: a 13 px line on a y axis, 7 px a character on an
/// x axis (UTF-8 continuation bytes take no room).
double line_height(const std::string&, const void*) { return 13; }
double text_width(const std::string& label, const void*) {
  double glyphs = 0;
  for (char c : label) glyphs += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return 7 * glyphs;
}

/// The pixel of v on an axis `length` long over range: an independent linear or log map.
double pixel_of(double v, const AxisRange& r, bool log, double length) {
  if (log) return length * std::log(v / r.lo) / std::log(r.hi / r.lo);
  return length * (v - r.lo) / (r.hi - r.lo);
}

}  // namespace

TEST_CASE("ticks_that_fit: at any plot size the tick labels' boxes never overlap") {
  struct Axis {
    AxisRange range;
    bool log;
  };
  const Axis axes[] = {{{-0.031, 0.047}, false}, {{0, 190}, false},    {{0, 3.2}, false},
                       {{1e-3, 1e3}, true},      {{0.4, 0.9}, true},   {{2.0, 3.1}, true},
                       {{-1e-14, 3e-14}, false}, {{10, 1e6}, true},    {{12.5, 12.75}, false}};
  for (const Axis& a : axes)
    for (bool vertical : {true, false})
      for (double length = 4; length <= 900; length *= 1.17) {
        AxisRoom room;
        room.length = length;
        room.label_length = vertical ? line_height : text_width;
        room.gap = vertical ? 3 : 10;
        const AxisTicks t = ticks_that_fit(a.range, a.log, room);
        CAPTURE(a.range.lo);
        CAPTURE(a.range.hi);
        CAPTURE(vertical);
        CAPTURE(length);
        REQUIRE(t.values.size() == t.labels.size());
        for (std::size_t i = 0; i + 1 < t.values.size(); ++i) {
          const double span = pixel_of(t.values[i + 1], a.range, a.log, length) -
                              pixel_of(t.values[i], a.range, a.log, length);
          const double needed = 0.5 * (room.label_length(t.labels[i], nullptr) +
                                       room.label_length(t.labels[i + 1], nullptr));
          CHECK(span >= needed + room.gap - 1e-9);
        }
        // Room for four labels and their gaps: at least two, so the axis tells its scale.
        if (vertical && length >= 4 * (13 + 3)) CHECK(t.values.size() >= 2);
      }
}

TEST_CASE("ticks_that_fit: with room to spare it gives what ticks_for gives for that room") {
  AxisRoom room;
  room.length = 400;
  room.label_length = line_height;
  room.gap = 3;
  const AxisTicks t = ticks_that_fit({0, 10}, false, room);
  // Each label is 16 px with its gap: 400 px hold many; the 1-2-5 rule still steps in 1s or 0.5s.
  CHECK(t.values.size() >= 6);
  CHECK(t.values.front() == 0);
  CHECK(t.values.back() == 10);
}
