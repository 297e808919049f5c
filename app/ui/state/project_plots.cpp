#include "ui/state/project_plots.h"

namespace swarmlab {

ProjectPlots project_plots_for(const swarm::Preset& p) {
  ProjectPlots plots;
  const bool moving_wall = !p.wall_moves.empty();
  const bool hot_wall = p.wall_temperature.has_value();
  plots.motion = p.gravity.has_value() || p.floor.has_value();
  plots.books = p.floor.has_value() || p.drag.has_value() || moving_wall || hot_wall;
  plots.pv_loop = moving_wall;
  // In any container: the wall's T is the temperature only for Maxwellian speeds, and the
  // read-outs show it beside T kinetic.
  plots.speeds = hot_wall || p.sphere_radius.has_value() || p.container_radius.has_value();
  return plots;
}

ProjectSeries project_series(const std::vector<swarm::Sample>& samples) {
  ProjectSeries s;
  if (samples.empty()) return s;
  const double E0 = samples.front().E;
  for (const swarm::Sample& x : samples) {
    s.t.push_back(x.t);
    s.cm_height.push_back(x.cm_height);
    s.size.push_back(x.size);
    s.wall_work.push_back(x.books.wall_work);
    s.wall_heat.push_back(x.books.wall_heat);
    s.drag_loss.push_back(x.books.drag_loss);
    s.net.push_back(x.books.net());
    s.energy_change.push_back(x.E - E0);
  }
  return s;
}

HistogramSeries histogram_series(const swarm::SpeedHistogram& h) {
  HistogramSeries s;
  const double width = h.density.empty() ? 0 : h.x_max / double(h.density.size());
  for (std::size_t b = 0; b < h.density.size(); ++b) {
    s.x.push_back((double(b) + 0.5) * width);
    s.measured.push_back(h.density[b]);
    s.maxwell.push_back(h.maxwell[b]);
  }
  return s;
}

}  // namespace swarmlab
