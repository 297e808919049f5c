#pragma once
// The two themes' colours, in one place so that a test can hold every text and line to WCAG AA
// (4.5:1 for text, 3:1 for lines and controls): the dark theme for a screen, the light
// high-contrast theme for a projector in a lit room.

#include "access/contrast.h"

namespace swarmlab {

enum class Theme { dark, light };

/// "dark" or "light" (the JS API's names).
const char* theme_name(Theme theme);

struct Palette {
  // Panels: the backgrounds text is drawn on, and the text.
  Colour window, popup, menu_bar, title, title_active;
  Colour frame, frame_hovered, frame_active;  ///< fields, sliders, check boxes
  Colour button, button_hovered, button_active;
  Colour header, header_hovered, header_active;  ///< collapsing headers, selected list rows
  Colour tab, tab_hovered, tab_active;
  Colour selected_row;  ///< the selected particle's row in the particle table
  Colour text, text_disabled, text_error, text_warning, text_ok, text_key;
  // Lessons (the lesson panel, the welcome): the lesson's title, *emphasised* words, and the
  // feedback to an answer that is right, not yet right, or recorded (a prediction, a note).
  Colour lesson_title, lesson_keyword, feedback_right, feedback_wrong, feedback_note;
  // Marks on the panels that must be seen (3:1 against what they sit on).
  Colour slider_grab, check_mark, nav_highlight, border, scrollbar_grab;
  // The 3D view.
  Colour view_background, view_text, legend_background, container, trail, selected, orbit_ahead,
      centre_of_mass, spring_attractive, spring_repulsive, ghost, axis_x, axis_y, axis_z;
  // Appendix B in the view: a hot wall's glass (hotter than the gas, as warm, colder), the
  // floor's grid and the arrow of gravity.
  Colour wall_hot, wall_neutral, wall_cold, floor_grid, gravity_arrow;
  // Plots.
  Colour plot_background, plot_grid, plot_axis, plot_text, plot_dim_text, crosshair;
  Colour pressure, pressure_each_sample, temperature, temperature_each_sample;
  Colour kinetic, potential, total_energy, fit;
  // The expansion's P-T plot (its P-V and T-V plots take pressure and temperature); the
  // Projects tab's energy-books sum (work + heat - drag loss), drawn wide under E - E0. The same
  // colour today, named twice so that either can change alone.
  Colour pressure_against_temperature, energy_books_sum;
  // The selected particle's x(t) plot: its curve, its start and its starting value; the
  // residuals of a power-law fit.
  Colour particle_track, particle_start, starting_value, residual;
  // The timeline under the view: the bar, the part computed so far, stage starts, the present
  // and where a seek or fast-forward goes.
  Colour timeline_track, timeline_reached, timeline_stage, timeline_present, timeline_target;
};

const Palette& palette(Theme theme);

/// A colour of the particle colour map (Turbo, blue = low, red = high) at x in [0, 1] for this
/// theme: every particle stands out at 3:1 from the view, so on the light view the bright
/// middle of the map is darkened, and on the dark view its darkest blues are brightened.
Colour particle_colour(float x, Theme theme);

/// A line colour given elsewhere (a method's colour in the core's method table) made to stand
/// out at 3:1 from this theme's plot background: darkened on the light theme, brightened on
/// the dark one, unchanged where it already does.
Colour plot_line_colour(Colour c, Theme theme);

/// Google's Turbo map (Mikhailov 2019), kept away from its darkest ends; x is clamped to [0, 1].
Colour turbo_colour(float x);

}  // namespace swarmlab
