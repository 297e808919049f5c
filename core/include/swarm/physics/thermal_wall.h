#pragma once
/// A container wall held at a temperature Tw (Appendix B): a particle that hits it is not
/// reflected but re-emitted with a velocity drawn from the wall's flux-weighted Maxwell
/// distribution at Tw. The normal speed is Rayleigh-distributed, p(v_n) ~ v_n exp(-m v_n^2 /
/// 2 Tw), because faster particles leave a wall more often per unit time; the two tangential
/// components are Gaussian with variance Tw / m (k_B = 1, T in energy units). The gas is
/// driven towards Tw and its velocities towards a Maxwellian.

#include <cstdint>

#include "swarm/physics/system.h"
#include "swarm/physics/wall.h"

namespace swarm {

/// The random numbers of one re-emission come from a counter-based generator keyed on the
/// run, the step and the particle, not from a stream: any engine, thread or order of hits
/// gives the same draws, and they are the same bits natively and in wasm (the core's own log,
/// sin, cos).
struct ThermalDraw {
  std::uint64_t step = 0;      ///< the engine's step count
  std::uint64_t particle = 0;  ///< the particle's index
  /// The run's own key (EngineConfig::wall_stream, a generated swarm's seed): the runs of an
  /// ensemble differ in it, so the same particle hitting in the same step of two runs does not
  /// draw the same velocity.
  std::uint64_t stream = 0;
};

/// Three numbers uniform in (0, 1] for the re-emission keyed by `key`.
void thermal_uniforms(const ThermalDraw& key, double u[3]);

/// Re-emits particle p, which hits the wall at its current position, into the container from
/// the flux-weighted Maxwellian at Tw. Records the hit (radial impulse m (|v_r in| + v_n out),
/// the kinetic energy it arrived with) and the heat the wall gave, 1/2 m (v_out^2 - v_in^2),
/// in tally.books.wall_heat.
void reemit_from_thermal_wall(Particle& p, double Tw, const ThermalDraw& key, WallTally& tally);

/// The same for a particle of mass m at r with velocity v: records the hit and the heat and
/// returns the velocity it leaves with.
Vec3 thermal_reemission(double m, const Vec3& r, const Vec3& v, double Tw, const ThermalDraw& key,
                        WallTally& tally);

}  // namespace swarm
