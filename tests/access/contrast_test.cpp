#include "access/contrast.h"

#include <doctest/doctest.h>

using namespace swarmlab;

// Reference values from the WCAG 2.x definitions (W3C "relative luminance" and "contrast
// ratio"), worked by hand or as published by the W3C and WebAIM.
TEST_CASE("relative luminance: black 0, white 1, and the linearised channels weighted") {
  CHECK(relative_luminance({0, 0, 0}) == doctest::Approx(0));
  CHECK(relative_luminance({255, 255, 255}) == doctest::Approx(1));
  CHECK(relative_luminance({255, 0, 0}) == doctest::Approx(0.2126));
  CHECK(relative_luminance({0, 255, 0}) == doctest::Approx(0.7152));
  CHECK(relative_luminance({0, 0, 255}) == doctest::Approx(0.0722));
  // 128/255 = 0.50196: ((0.50196 + 0.055) / 1.055)^2.4 = 0.21586.
  CHECK(relative_luminance({128, 128, 128}) == doctest::Approx(0.21586).epsilon(1e-4));
}

TEST_CASE("contrast ratio: 21:1 for black on white, symmetric, and the AA grey threshold") {
  CHECK(contrast_ratio({0, 0, 0}, {255, 255, 255}) == doctest::Approx(21));
  CHECK(contrast_ratio({255, 255, 255}, {0, 0, 0}) == doctest::Approx(21));
  CHECK(contrast_ratio({90, 90, 90}, {90, 90, 90}) == doctest::Approx(1));
  // The well-known pair: #767676 is the lightest grey passing 4.5:1 on white, #777777 fails.
  CHECK(contrast_ratio({0x76, 0x76, 0x76}, {255, 255, 255}) >= 4.5);
  CHECK(contrast_ratio({0x77, 0x77, 0x77}, {255, 255, 255}) < 4.5);
}

TEST_CASE("a translucent colour is judged as it is seen: blended over its background") {
  // Half-covering white over black is sRGB 128 (rounded): the ratio of that grey to black.
  const Colour half_white{255, 255, 255, 128};
  CHECK(over(half_white, {0, 0, 0}).r == 128);
  CHECK(contrast_ratio(half_white, {0, 0, 0}) ==
        doctest::Approx((relative_luminance({128, 128, 128}) + 0.05) / 0.05));
  // Fully transparent: nothing is seen, 1:1.
  CHECK(contrast_ratio({255, 255, 255, 0}, {10, 20, 30}) == doctest::Approx(1));
}

TEST_CASE("darkened_to keeps dark colours and brings bright ones down to the luminance asked") {
  const Colour navy{20, 30, 90};
  const Colour kept = darkened_to(navy, 0.3);
  CHECK(kept.packed() == navy.packed());
  const Colour yellow{250, 230, 40};
  const Colour d = darkened_to(yellow, 0.2);
  CHECK(relative_luminance(d) <= 0.2);
  CHECK(relative_luminance(d) > 0.19);  // not darker than needed
  // Hue kept: red stays above green above blue.
  CHECK(d.r > d.g);
  CHECK(d.g > d.b);
}

TEST_CASE("brightened_to keeps bright colours and lifts dark ones to the luminance asked") {
  const Colour sky{120, 200, 255};
  CHECK(brightened_to(sky, 0.2).packed() == sky.packed());
  const Colour navy{30, 20, 90};
  const Colour b = brightened_to(navy, 0.12);
  CHECK(relative_luminance(b) >= 0.12);
  CHECK(relative_luminance(b) < 0.13);
  CHECK(b.b > b.r);  // still blue
  CHECK(b.r > b.g);
  CHECK(relative_luminance(brightened_to({0, 0, 0}, 0.5)) >= 0.5);
}
