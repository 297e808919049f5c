#pragma once
// The panels of the window. Each draws one part of the controls into the current ImGui window
// and edits the AppState; edits to the preset go through AppState::apply_draft.

#include "ui/state/app_state.h"

namespace swarmlab {

void draw_scenario_panel(AppState& state);
void draw_system_panel(AppState& state);
void draw_container_panel(AppState& state);
/// Gravity, a floor and drag (Appendix B).
void draw_forces_panel(AppState& state);
/// Appendix B: a moving or hot wall, and particles as hard spheres.
void draw_walls_panel(AppState& state);
void draw_simulation_panel(AppState& state);
void draw_view_panel(AppState& state);
/// The live plots (right-hand panel).
void draw_plots_panel(AppState& state);
/// The read-outs over the 3D view, each with its equation on hover.
void draw_readouts(AppState& state);
/// Play, pause, step, reset, speed and the clock, over the top of the 3D view.
void draw_transport_bar(AppState& state);
/// The stopwatch, the period meter and the selected particle's card (instruments_panel.cpp,
/// particle_card.cpp): at the top of the Plots panel in the wide layout, a drawer tab in the
/// compact ones, so that they never cover the swarm.
void draw_instruments(AppState& state);
void draw_particle_card(AppState& state);
/// The selected particle's x(t) about the centre of mass, a plot tab (particle_plot.cpp).
void draw_particle_tab(AppState& state, float plot_height);
/// The plots of the Appendix B projects that fit the preset, a plot tab (projects_plot_tab.cpp),
/// and how many of them it draws.
void draw_projects_tab(AppState& state, float plot_height);
int project_plot_count(const swarm::Preset& preset);

// Helpers shared by the panels.

/// Shows the reason the last edit in `section` was refused, with a button to drop it.
void show_refusal(AppState& state, Section section);
/// A "(?)" that explains the control before it on hover.
void help_marker(const char* text);
/// Whether the item just drawn was changed and released (slider let go, Enter, focus left):
/// typed and dragged values are applied then, not at every keystroke.
bool committed();
/// A field for a double, any value typed; says whether an edit was committed (see committed).
/// (number_field.cpp)
bool input_double(const char* label, double* value, const char* format = "%.6g");

}  // namespace swarmlab
