#pragma once
// The P-V loop of a moving wall from a run's samples, split into the way in and the way out:
// one definition for the CLI's pv-loop figure and the app's Projects tab.

#include <vector>

#include "swarm/run/run.h"

namespace swarmlab::report {

/// P against V = 4/3 pi (R - a)^3 (the ball the centres reach, whose sphere P divides by;
/// a = 0 for point particles), split where the wall is innermost: the way in (squeezing) and
/// the way out. Each sample's P is over a few steps and a few hits, so P is the running wall
/// average over `half_window` (time) either side of each sample (swarm::windowed_wall_averages).
/// The way out starts at the last point of the way in, so the loop is unbroken.
struct PvLoop {
  std::vector<double> V_in, P_in, V_out, P_out;
};
PvLoop pv_loop(const std::vector<swarm::Sample>& samples, double half_window,
               double sphere_radius);

}  // namespace swarmlab::report
