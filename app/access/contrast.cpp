#include "access/contrast.h"

#include <algorithm>
#include <cmath>

namespace swarmlab {
namespace {

double linear(std::uint8_t channel) {
  const double c = channel / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

std::uint8_t encoded(double linear_channel) {
  const double l = std::clamp(linear_channel, 0.0, 1.0);
  const double c = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
  return std::uint8_t(std::lround(c * 255.0));
}

}  // namespace

Colour over(Colour top, Colour bottom) {
  const double a = top.a / 255.0;
  auto mix = [a](std::uint8_t t, std::uint8_t b) {
    return std::uint8_t(std::lround(a * t + (1 - a) * b));
  };
  return {mix(top.r, bottom.r), mix(top.g, bottom.g), mix(top.b, bottom.b), 255};
}

double relative_luminance(Colour c) {
  return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

double contrast_ratio(Colour foreground, Colour background) {
  background.a = 255;
  const double a = relative_luminance(over(foreground, background));
  const double b = relative_luminance(background);
  return (std::max(a, b) + 0.05) / (std::min(a, b) + 0.05);
}

Colour darkened_to(Colour c, double max_luminance) {
  const double L = relative_luminance(c);
  if (L <= max_luminance) return c;
  // Relative luminance is linear in the linear channels: scaling them all by k scales it by k.
  // Rounding back to 8 bits can land a hair above; step down until it does not.
  for (double k = max_luminance / L;; k *= 0.99) {
    const Colour d{encoded(k * linear(c.r)), encoded(k * linear(c.g)), encoded(k * linear(c.b)),
                   c.a};
    if (relative_luminance(d) <= max_luminance) return d;
  }
}

Colour brightened_to(Colour c, double min_luminance) {
  const double L = relative_luminance(c);
  if (L >= min_luminance) return c;
  // Black has no hue to keep: a grey of the luminance asked.
  if (L < 1e-6) c = {1, 1, 1, c.a};
  // Channels that reach 1 stop there, so the scale grows until the others make up the rest.
  for (double k = min_luminance / std::max(L, 1e-6);; k *= 1.02) {
    const Colour b{encoded(k * linear(c.r)), encoded(k * linear(c.g)), encoded(k * linear(c.b)),
                   c.a};
    if (relative_luminance(b) >= min_luminance) return b;
  }
}

}  // namespace swarmlab
