#include "swarm/physics/wall.h"

#include <cmath>

namespace swarm {

void reflect_at_wall(Particle& p, WallTally& tally) { p.v += wall_reflection(p.m, p.r, p.v, tally); }

double sphere_area(double R) { return 4 * M_PI * R * R; }
double swept_area(double R0, double R1) { return 4.0 / 3.0 * M_PI * (R0 * R0 + R0 * R1 + R1 * R1); }
double sphere_volume(double R) { return 4.0 / 3.0 * M_PI * R * R * R; }

}  // namespace swarm
