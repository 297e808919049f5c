#pragma once
// A plot's export carried out for the app: the request its menu left (plot_export_menu.h) goes
// to the save dialog, and a PNG is read from the screen once a frame is drawn without the menu.
// The one part of the plots that needs the AppState, above it.

#include <string>

namespace swarmlab {

struct AppState;

/// Once a frame: an SVG or CSV asked for goes to the save dialog (save_dialog.h); a PNG waits
/// for a frame drawn without the menu.
void handle_plot_export(AppState& state);
/// After the frame is drawn and before it is shown: reads a waiting PNG's pixels from the
/// framebuffer and hands the file to the save dialog (glReadPixels: desktop GL3 and WebGL2).
void capture_plot_png(AppState& state);

/// PNG bytes of an RGBA image stored bottom row first (as OpenGL reads it); empty on failure.
std::string png_of_gl_pixels(const unsigned char* rgba, int width, int height);

}  // namespace swarmlab
