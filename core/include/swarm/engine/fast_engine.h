#pragma once
/// The fast engine: Appendix A (paper collisions, analytic method) at a cost that grows with
/// the number of wall hits rather than with N times the number of steps.
///
/// Each lab position is split as r_i(t) = y_i(t) + o(t). y_i is a free oscillator about the
/// origin (y'' = -k y, k = J M; under mass-proportional drag gamma, the damped y'' = -k y -
/// gamma y') that changes only at particle i's own wall hits; o = R_cm - Y,
/// with Y = sum m_i y_i / M, is one shared 3-vector. Right after a re-base y_i is particle i's
/// displacement from the CM and Y = 0; later hits move Y away from 0. A hit of particle j changes
/// v_j by dv: that is y_j's velocity alone, plus m_j dv / M on the shared R_cm and Y velocities,
/// whose difference o' does not change. So a hit costs O(1), not O(N).
///
/// |y_i(t)|^2 is a constant plus a sinusoid in 2 omega t (exponentials for J < 0, a quadratic
/// for J = 0), so the first time particle i can come within a margin G of the wall is known
/// in closed form (core/src/engine/fast_engine_window.h); under drag it is that times the
/// decaying exp(-gamma t), bounded by its value when the window is made. Gravity moves only
/// R_cm, along a parabola; an elastic floor is a plane wall with a window of its own, for the
/// times y_i's z can be below it; a particle is checked only in the steps it
/// is due, which a timing wheel keeps (core/src/engine/timing_wheel.h). Within a few steps of that
/// window its exact predicted positions at the next step ends are looked at
/// (core/src/engine/fast_engine_lookahead.h), so it is checked again only when it can actually hit.
/// Positions are materialised only when system() is called.
///
/// The margin G must bound |o|. An "anchor" (core/src/engine/fast_engine_anchor.h) fixes the
/// coordinates a schedule is made in: y_i minus Y's path as it was when the anchor was set, so
/// that the anchor's offset moves only with the CM and the later kicks. A particle keeps its
/// window, and the anchor it was made in, until its next hit; the anchor stays valid while its
/// offset stays within its margin, which is checked every step, and when it does not the
/// particles relying on it are rescheduled (with a floor, the anchor also keeps o's height
/// above a level, for the floor's windows). When J < 0 the kicks' effect grows like
/// exp(Omega t), so a new anchor is set every few steps (O(1)), and under gravity or drag,
/// whose CM the wall keeps moving, new anchors come in O(1) too; the engine also re-bases now
/// and then, folding Y into every y_i (O(N)), to keep the digits of the y_i, which the
/// anchors carry over.
///
/// The particles are split by index into one lane per thread (EngineConfig::threads; run by
/// core/src/engine/lane_pool.h). A step's hits are combined in particle-id order and the O(N)
/// sums in fixed blocks in block order, so the results do not depend on the thread count.
///
/// The wall may move (EngineConfig::wall_moves: its radius is linear in time between moves) or
/// be hot (EngineConfig::wall_temperature). A hit only needs dv, whatever the wall does:
/// a moving wall reverses the velocity relative to it, a thermal wall re-emits the particle
/// with the velocity the reference engine draws for it in that step (the same ThermalDraw
/// keys), and either puts the particle on a new closed-form orbit like any hit
/// (core/src/engine/fast_engine_wall.h). A moving wall spends the anchors' margin as the CM
/// does: an anchor made for radius R stays valid while its offset at a step end is within
/// margin - (R - R_end), R_end the wall's radius then, so a wall that closes in expires it;
/// the lookahead judges against the least radius the wall has over its steps. The wall's
/// rules and the forces' flow compose: a hit's dv, whatever the wall, goes into the
/// coefficients through the (damped) flow, and the floor is checked after the wall on the same
/// prediction, as in the reference engine; an anchor holds while both the wall's radius rule
/// and the floor's level hold.
///
/// The engine reproduces the reference engine's wall hits step by step (same predicate on the
/// same prediction, evaluated from an algebraically identical state) up to rounding.

#include <cstddef>
#include <cstdint>
#include <memory>

#include "swarm/engine/engine.h"

namespace swarm {

/// Whether make_fast_engine can run this configuration: the analytic method with paper
/// collisions (with a container or without: isolated, it is the analytic solution), the wall
/// fixed, moving or hot, also under gravity, mass-proportional drag and an elastic floor. Not
/// drag b on chosen particles (each particle's own rate couples them all through the CM: no
/// closed form per particle), an inelastic floor (particles come to rest on it), hard spheres.
bool fast_engine_applies(const EngineConfig& config);

/// The most particles the fast engine takes (ids are packed into 26 bits).
inline constexpr std::size_t kMaxFastEngineParticles = std::size_t(1) << 26;

/// Throws std::invalid_argument when !fast_engine_applies(config) or there are more than
/// kMaxFastEngineParticles particles.
std::unique_ptr<Engine> make_fast_engine(System initial, const EngineConfig& config);

/// Work counters of a fast engine, for benchmarks and tests.
struct FastEngineStats {
  std::int64_t checks = 0;          ///< particles whose hit predicate was evaluated
  std::int64_t hits = 0;            ///< wall hits (floor bounces not included)
  std::int64_t rebases = 0;         ///< O(N) re-bases (each sets a new anchor)
  std::int64_t reschedules = 0;     ///< O(N) full reschedules (radius or dt changed)
  std::int64_t expired = 0;         ///< particles rescheduled because their anchor expired
  std::int64_t parallel_steps = 0;  ///< steps whose checks ran on several threads
  /// Under gravity: the push of the wall and the floor on the CM that the anchors' forecast
  /// takes in (length/time^2), a running mean of the kicks over the forecast's horizon.
  Vec3 wall_push = Vec3::Zero();
};

/// The counters of engine if it is a fast engine, else nothing.
std::optional<FastEngineStats> fast_engine_stats(const Engine& engine);

}  // namespace swarm
