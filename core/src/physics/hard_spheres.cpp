#include "swarm/physics/hard_spheres.h"

#include "physics/cell_grid.h"

namespace swarm {

bool collide_spheres(Particle& p, Particle& q) {
  const Vec3 d = p.r - q.r;
  const double approach = (p.v - q.v).dot(d);
  if (approach >= 0) return false;
  // The impulse along the unit normal d / |d| that reverses the normal relative velocity:
  // j = 2 m_p m_q / (m_p + m_q) * (v_rel . d) / |d|^2, applied along d.
  const double j = 2 * approach / ((p.m + q.m) * d.squaredNorm());
  p.v -= (j * q.m) * d;
  q.v += (j * p.m) * d;
  return true;
}

HardSpheres::HardSpheres(double radius) : radius_(radius), grid_(std::make_unique<CellGrid>()) {}
HardSpheres::~HardSpheres() = default;
HardSpheres::HardSpheres(const HardSpheres& other) : HardSpheres(other.radius_) {}
HardSpheres::HardSpheres(HardSpheres&&) noexcept = default;
HardSpheres& HardSpheres::operator=(HardSpheres&&) noexcept = default;

std::int64_t HardSpheres::collide(std::vector<Particle>& particles) {
  const double contact = 2 * radius_;
  const double contact2 = contact * contact;
  grid_->build(particles, contact);
  std::int64_t collisions = 0;
  grid_->for_each_neighbour_pair([&](std::uint32_t i, std::uint32_t k) {
    Particle& p = particles[i];
    Particle& q = particles[k];
    if ((p.r - q.r).squaredNorm() < contact2 && collide_spheres(p, q)) ++collisions;
  });
  return collisions;
}

}  // namespace swarm
