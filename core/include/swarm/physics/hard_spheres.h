#pragma once
/// Particles as hard spheres of one radius a (Appendix B): two that touch while approaching
/// collide elastically, exchanging the components of their velocities along the line of
/// centres (weighted by mass). A contact conserves momentum and kinetic energy exactly in
/// exact arithmetic, so the centre-of-mass picture survives between contacts; with a
/// container, a sphere reaches the wall when its centre is at R - a.
///
/// Contacts are found at the end of each step, in the style of Appendix A's wall: a pair that
/// overlaps (|r_i - r_j| < 2a) and is approaching is collided at its current positions. The
/// error is of order |v| dt / a: dt must be small against the time to cross a radius.

#include <cstdint>
#include <memory>
#include <vector>

#include "swarm/physics/system.h"

namespace swarm {

class CellGrid;

/// The elastic collision of particles p and q along the line of their centres, if they are
/// approaching; returns whether it happened.
bool collide_spheres(Particle& p, Particle& q);

/// Finds the contacts among the particles in O(N) with a cell grid, keeping its storage
/// between steps.
class HardSpheres {
 public:
  explicit HardSpheres(double radius);
  ~HardSpheres();
  /// A copy (a timeline snapshot) starts with empty storage: the grid is rebuilt every step.
  HardSpheres(const HardSpheres& other);
  HardSpheres(HardSpheres&&) noexcept;
  HardSpheres& operator=(HardSpheres&&) noexcept;

  /// Collides every overlapping, approaching pair, in a fixed order (cells, then indices);
  /// returns how many collided.
  std::int64_t collide(std::vector<Particle>& particles);
  double radius() const { return radius_; }

 private:
  double radius_;
  std::unique_ptr<CellGrid> grid_;
};

}  // namespace swarm
