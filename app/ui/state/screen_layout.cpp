#include "ui/state/screen_layout.h"

#include <algorithm>
#include <cmath>

namespace swarmlab {
namespace {

// Widths in font sizes, so that a larger UI scale widens the panels with their text.
constexpr float kControlsWidth = 22, kPlotsWidth = 25;
/// The wide layout needs at least this much of the width left for the view (and no less
/// than kMinViewShare of the window), and this much height; below, the compact layouts.
constexpr float kMinViewWidth = 30, kMinViewShare = 0.35f, kMinWideHeight = 30;
/// Before the first frame has measured them.
constexpr float kTransportGuess = 2.7f, kReadoutsGuess = 6;

/// Whole pixels: neighbours share an edge, rounded alike, so they never overlap.
ScreenRect rect(float x, float y, float width, float height) {
  const float x0 = std::round(x), y0 = std::round(y);
  return {x0, y0, std::max(std::round(x + width) - x0, 0.0f),
          std::max(std::round(y + height) - y0, 0.0f)};
}

}  // namespace

const char* layout_name(LayoutKind kind) {
  switch (kind) {
    case LayoutKind::wide: return "wide";
    case LayoutKind::portrait: return "portrait";
    case LayoutKind::landscape: return "landscape";
  }
  return "wide";
}

const char* layout_mode_name(LayoutMode mode) {
  switch (mode) {
    case LayoutMode::automatic: return "auto";
    case LayoutMode::wide: return "wide";
    case LayoutMode::compact: return "compact";
  }
  return "auto";
}

bool parse_layout_mode(const std::string& text, LayoutMode& mode) {
  for (LayoutMode m : {LayoutMode::automatic, LayoutMode::wide, LayoutMode::compact})
    if (text == layout_mode_name(m)) {
      mode = m;
      return true;
    }
  return false;
}

LayoutKind choose_layout(const ScreenLayoutInput& in) {
  const float f = in.font;
  const bool wide_fits = in.width >= (kControlsWidth + kPlotsWidth) * f +
                                         std::max(kMinViewWidth * f, kMinViewShare * in.width) &&
                         in.height >= kMinWideHeight * f;
  if (in.mode == LayoutMode::wide || (in.mode == LayoutMode::automatic && wide_fits))
    return LayoutKind::wide;
  return in.height > in.width ? LayoutKind::portrait : LayoutKind::landscape;
}

ScreenLayout screen_layout(const ScreenLayoutInput& in) {
  const float f = in.font, top = in.menu_height, bottom = in.height;
  const float transport = in.transport_height > 0 ? in.transport_height : kTransportGuess * f;
  const float strip = std::max(in.bottom_strip_height, 0.0f);
  ScreenLayout out;
  out.kind = choose_layout(in);

  if (out.kind == LayoutKind::wide) {
    // Each side panel keeps its width while the view keeps at least 40% of the window.
    float controls = in.controls ? kControlsWidth * f : 0, plots = in.plots ? kPlotsWidth * f : 0;
    const float squeeze = std::min(1.0f, 0.6f * in.width / std::max(controls + plots, 1.0f));
    controls *= squeeze, plots *= squeeze;
    if (in.controls) out.controls = rect(0, top, controls, bottom - top);
    if (in.plots) out.plots = rect(in.width - plots, top, plots, bottom - top);
    const float x = controls, w = in.width - controls - plots;
    out.transport = rect(x, top, w, transport);
    // The read-outs take what they need under the view, but never more than a third of it.
    const float readouts = std::min(in.readouts_height > 0 ? in.readouts_height : kReadoutsGuess * f,
                                    (bottom - top - transport - strip) / 3);
    out.bottom_strip = rect(x, bottom - strip, w, strip);
    out.readouts = rect(x, bottom - strip - readouts, w, readouts);
    out.view = rect(x, top + transport, w, out.readouts.y - top - transport);
    return out;
  }

  const bool drawer = in.controls || in.plots;
  if (out.kind == LayoutKind::portrait) {
    // The view first, as tall as the window is wide when the drawer leaves room for that.
    const float below = top + transport;
    const float room = bottom - below - strip;
    const float view = drawer ? std::min(in.width, 0.5f * room) : room;
    out.transport = rect(0, top, in.width, transport);
    out.view = rect(0, below, in.width, view);
    out.bottom_strip = rect(0, below + view, in.width, strip);
    if (drawer) out.drawer = rect(0, below + view + strip, in.width, bottom - below - view - strip);
  } else {
    const float width =
        drawer ? std::clamp(0.42f * in.width, std::min(18 * f, 0.5f * in.width), 28 * f) : 0;
    const float left = in.width - width;
    out.transport = rect(0, top, left, transport);
    out.view = rect(0, top + transport, left, bottom - top - transport - strip);
    out.bottom_strip = rect(0, bottom - strip, left, strip);
    if (drawer) out.drawer = rect(left, top, width, bottom - top);
  }
  return out;  // the read-outs are a tab of the drawer
}

}  // namespace swarmlab
