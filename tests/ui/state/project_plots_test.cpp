#include "ui/state/project_plots.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarmlab;

TEST_CASE("project_plots: each Appendix B feature calls for its plots, none for a plain swarm") {
  swarm::Preset plain;
  CHECK_FALSE(project_plots_for(plain).any());

  swarm::Preset falling;
  falling.gravity = swarm::Vec3(0, 0, -1);
  ProjectPlots p = project_plots_for(falling);
  CHECK(p.motion);
  CHECK_FALSE(p.books);  // gravity alone exchanges no energy with the outside
  CHECK_FALSE(p.pv_loop);
  CHECK_FALSE(p.speeds);

  swarm::Preset bouncing;
  bouncing.floor = swarm::Floor{0, 0.8};
  p = project_plots_for(bouncing);
  CHECK(p.motion);
  CHECK(p.books);

  swarm::Preset dragged;
  dragged.drag = swarm::Drag{0.5, 0, {}};
  p = project_plots_for(dragged);
  CHECK(p.books);
  CHECK_FALSE(p.motion);

  swarm::Preset piston;
  piston.wall_moves = {swarm::WallMove{0.5, 0.1}, swarm::WallMove{1.0, 0.1}};
  p = project_plots_for(piston);
  CHECK(p.books);
  CHECK(p.pv_loop);
  CHECK_FALSE(p.speeds);

  swarm::Preset hot;
  hot.wall_temperature = 2.0;
  p = project_plots_for(hot);
  CHECK(p.books);
  CHECK(p.speeds);
  CHECK_FALSE(p.pv_loop);

  swarm::Preset spheres;
  spheres.sphere_radius = 0.05;
  p = project_plots_for(spheres);
  CHECK(p.speeds);
  CHECK_FALSE(p.books);  // elastic contacts exchange no energy with the outside

  // A plain container: whether the wall's T is the temperature depends on the speeds.
  swarm::Preset gas;
  gas.container_radius = 1.0;
  p = project_plots_for(gas);
  CHECK(p.speeds);
  CHECK_FALSE(p.books);
  CHECK_FALSE(p.motion);
}

TEST_CASE("project_plots: the books' sum and E - E0 from the samples") {
  std::vector<swarm::Sample> samples(2);
  samples[0].E = 3.0;
  samples[1].t = 0.5;
  samples[1].E = 3.25;
  samples[1].cm_height = 1.5;
  samples[1].size = 0.7;
  samples[1].books.wall_work = 0.5;
  samples[1].books.wall_heat = -0.125;
  samples[1].books.drag_loss = 0.125;
  const ProjectSeries s = project_series(samples);
  REQUIRE(s.t.size() == 2);
  CHECK(s.energy_change[0] == 0);
  CHECK(s.energy_change[1] == doctest::Approx(0.25));
  CHECK(s.net[1] == doctest::Approx(0.5 - 0.125 - 0.125));  // work + heat - drag loss
  CHECK(s.cm_height[1] == 1.5);
  CHECK(s.size[1] == 0.7);
}

TEST_CASE("project_plots: the histogram series at the bin centres beside the Maxwell density") {
  // Four speeds in four bins of width 1: densities 1/4, 2/4, 0, 1/4 per unit of x.
  const swarm::SpeedHistogram h = swarm::speed_histogram({0.5, 1.2, 1.7, 3.5}, 4, 4.0);
  const HistogramSeries s = histogram_series(h);
  REQUIRE(s.x.size() == 4);
  const double pi = std::acos(-1.0);
  const double expected[] = {0.25, 0.5, 0.0, 0.25};
  for (int b = 0; b < 4; ++b) {
    const double x = b + 0.5;
    CHECK(s.x[b] == doctest::Approx(x));
    CHECK(s.measured[b] == doctest::Approx(expected[b]));
    CHECK(s.maxwell[b] == doctest::Approx(std::sqrt(2 / pi) * x * x * std::exp(-x * x / 2)));
  }
  CHECK(histogram_series(swarm::SpeedHistogram{}).x.empty());
}
