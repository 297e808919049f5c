#pragma once
// Where the panels go: a pure function from the window's size, the font size (the UI scale)
// and the chosen layout to the rectangles of the 3D view, the strips around it and the panels.
// No ImGui here, so that the layouts can be checked at every screen size without a window.

#include <string>
#include <vector>

namespace swarmlab {

/// What the user chose in the View menu: automatic picks from the window size.
enum class LayoutMode { automatic, wide, compact };

/// The layout in use.
///  wide:     controls | transport, view, read-outs, bottom strip | plots (desktop, 1280 px up).
///  portrait: transport, view, bottom strip, then one drawer of tabs below (phone upright).
///  landscape: transport, view, bottom strip on the left, the drawer of tabs on the right
///            (tablet, phone on its side, a projector at a large UI scale).
enum class LayoutKind { wide, portrait, landscape };

const char* layout_name(LayoutKind kind);
/// "auto", "wide", "compact"; parse_layout_mode returns false for anything else.
const char* layout_mode_name(LayoutMode mode);
bool parse_layout_mode(const std::string& text, LayoutMode& mode);

/// A rectangle of the window in pixels, origin at the top left; zero size when not shown.
struct ScreenRect {
  float x = 0, y = 0, width = 0, height = 0;
  bool shown() const { return width > 0 && height > 0; }
  float right() const { return x + width; }
  float bottom() const { return y + height; }
};

struct ScreenLayoutInput {
  float width = 1280, height = 720;  ///< the window, pixels
  float font = 16;                   ///< font size in pixels (16 x UI scale)
  float menu_height = 0;             ///< the main menu bar along the top
  LayoutMode mode = LayoutMode::automatic;
  bool controls = true, plots = true;  ///< the panels the user has open
  /// Measured on the previous frame (0 before the first): the transport bar's height and the
  /// read-outs' height when laid out across `width` of the wide layout's middle column.
  float transport_height = 0, readouts_height = 0;
  /// Reserved under the view for other strips (a timeline), pixels.
  float bottom_strip_height = 0;
};

struct ScreenLayout {
  LayoutKind kind = LayoutKind::wide;
  ScreenRect view;          ///< the 3D view: nothing is drawn over it but its own overlay
  ScreenRect transport;     ///< play, pause, speed, clock: above the view
  ScreenRect readouts;      ///< wide: a strip under the view (compact: a tab of the drawer)
  ScreenRect bottom_strip;  ///< under the view (and the read-outs), bottom_strip_height tall
  ScreenRect controls, plots;  ///< wide: the side panels
  ScreenRect drawer;           ///< compact: Controls, Plots and Read-outs as tabs
};

/// The layout that mode resolves to at this size and font.
LayoutKind choose_layout(const ScreenLayoutInput& in);
/// The rectangles of every part; they never overlap and stay inside the window.
ScreenLayout screen_layout(const ScreenLayoutInput& in);

}  // namespace swarmlab
