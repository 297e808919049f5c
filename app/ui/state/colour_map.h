#pragma once
// Colouring particles by a physical quantity, and the colour map shared by the 3D view and
// its legend.

#include <cstdint>

#include "swarm/physics/system.h"

namespace swarmlab {

enum class ColourBy { speed, mass, energy };

/// The quantity with its symbol and unit, for the legend.
const char* legend_title(ColourBy c);

/// Packed 0xAABBGGRR (ImGui's ImU32 and the byte order of the particle vertex buffer).
using Rgba8 = std::uint32_t;

/// "Turbo" (Google's rainbow map, blue = low, red = high): bright enough at both ends to stand
/// out against the dark background. x is clamped to [0, 1].
Rgba8 turbo(float x, std::uint8_t alpha = 255);

/// The value of the chosen quantity for one particle. Energy is the particle's kinetic energy
/// plus its spring energy about the centre of mass, 1/2 J M m |r - R_cm|^2.
struct ParticleQuantity {
  ColourBy by = ColourBy::speed;
  swarm::Vec3 cm = swarm::Vec3::Zero();
  double stiffness = 0;  ///< J M

  double operator()(const swarm::Particle& p) const;
};

/// Maps a value range onto the colour map. The range follows the data smoothly so that the
/// legend does not flicker from frame to frame.
struct ColourScale {
  double lo = 0, hi = 1;
  bool initialised = false;
  /// Fixed by the user: a colour keeps meaning the same value (follow() changes nothing).
  bool locked = false;

  void follow(double data_lo, double data_hi);
  float position(double value) const;  ///< 0 at lo, 1 at hi
  Rgba8 colour(double value) const { return turbo(position(value)); }
};

}  // namespace swarmlab
