#pragma once
// WCAG 2.x contrast: the relative luminance of an sRGB colour and the ratio between two, the
// measure the themes are held to (4.5:1 for text, 3:1 for lines and other graphics).

#include <cstdint>

namespace swarmlab {

/// An 8-bit sRGB colour with coverage a (255: opaque).
struct Colour {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;

  /// Packed 0xAABBGGRR: ImGui's ImU32 and the particle vertex buffer's byte order.
  std::uint32_t packed() const {
    return std::uint32_t(r) | std::uint32_t(g) << 8 | std::uint32_t(b) << 16 |
           std::uint32_t(a) << 24;
  }
  static Colour from_packed(std::uint32_t c) {
    return {std::uint8_t(c), std::uint8_t(c >> 8), std::uint8_t(c >> 16), std::uint8_t(c >> 24)};
  }
};

/// What the eye sees of `top` drawn over the opaque `bottom` (alpha blending in sRGB, as the
/// renderer blends).
Colour over(Colour top, Colour bottom);

/// WCAG 2.x relative luminance in [0, 1] (alpha ignored): 0.2126 R + 0.7152 G + 0.0722 B of
/// the linearised channels.
double relative_luminance(Colour c);

/// WCAG 2.x contrast ratio (L_lighter + 0.05) / (L_darker + 0.05), in [1, 21]. `foreground` is
/// first blended over the opaque `background`.
double contrast_ratio(Colour foreground, Colour background);

/// The same hue darkened (all linear channels scaled alike) until its relative luminance is at
/// most `max_luminance`; colours already dark enough are returned unchanged.
Colour darkened_to(Colour c, double max_luminance);

/// The same hue brightened (all linear channels scaled alike, each at most 1) until its
/// relative luminance is at least `min_luminance`; colours already bright enough are returned
/// unchanged.
Colour brightened_to(Colour c, double min_luminance);

}  // namespace swarmlab
