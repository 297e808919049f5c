#pragma once
// The plot tabs by name. Their order on screen, and the numbers of the desktop's --plot-tab,
// follow this list; what each draws and how tall its plots are is the plots panel's table
// (plots_panel.cpp). Everything else (the app's state, lessons, the adapters) names a tab.

namespace swarmlab {

enum class PlotTab { wall, energy, expansion, compare, particle, projects };

/// How many tabs there are: --plot-tab takes 1 to this.
inline constexpr int kPlotTabCount = 6;

/// The tab numbered n from 1, left to right, as --plot-tab counts (n in 1..kPlotTabCount).
inline PlotTab plot_tab_numbered(int n) { return PlotTab(n - 1); }

}  // namespace swarmlab
