#pragma once
/// The fast engine: Appendix A (paper collisions, analytic method) at a cost that grows with
/// the number of wall hits rather than with N times the number of steps.
///
/// Each lab position is split as r_i(t) = y_i(t) + o(t). y_i is a free oscillator about the
/// origin (y'' = -k y) that changes only at particle i's own wall hits; o = R_cm - Y, with
/// Y = sum m_i y_i / M, is one shared 3-vector (the h_i and g, with the h_i taken
/// about the CM at each re-base). A hit of particle j changes v_j by dv: that is y_j's
/// velocity alone, plus m_j dv / M on the shared R_cm and Y velocities, whose difference o'
/// does not change. So a hit costs O(1), not O(N).
///
/// |y_i(t)|^2 is a constant plus a sinusoid in 2 omega t (exponentials for J < 0, a quadratic
/// for J = 0), so the first time particle i can come within a margin G of the wall is known
/// in closed form; a particle is checked only in the steps it is due, which are kept in a ring
/// of per-step buckets. Within a few steps of that window its exact predicted positions at
/// the next step ends are looked at, so it is checked again only when it can actually hit.
/// Positions are materialised only when system() is called.
///
/// The margin G must bound |o|. A "frame" fixes the coordinates a schedule is made in: y_i
/// minus Y's path as it was when the frame began, so that the frame's offset moves only with
/// the CM and the later kicks. A particle keeps its window, and the frame it was made in,
/// until its next hit; the frame stays valid while its offset stays within its margin, which
/// is checked every step, and when it does not the particles relying on it are rescheduled.
/// When J < 0 the kicks' effect grows like exp(Omega t), so a new frame starts every few
/// steps (O(1)); the engine also re-bases now and then, folding Y into every y_i (O(N)),
/// to keep the digits of the y_i, which the frames carry over.
///
/// The engine reproduces the reference engine's wall hits step by step (same predicate on the
/// same prediction, evaluated from an algebraically identical state) up to rounding.

#include <cstddef>
#include <cstdint>
#include <memory>

#include "swarm/engine.h"

namespace swarm {

/// Whether make_fast_engine can run this configuration: the analytic method with paper
/// collisions, or an isolated system.
bool fast_engine_applies(const EngineConfig& config);

/// The most particles the fast engine takes (ids are packed into 26 bits).
inline constexpr std::size_t kMaxFastEngineParticles = std::size_t(1) << 26;

/// Throws std::invalid_argument when !fast_engine_applies(config) or there are more than
/// kMaxFastEngineParticles particles.
std::unique_ptr<Engine> make_fast_engine(System initial, const EngineConfig& config);

/// Work counters of a fast engine, for benchmarks and tests.
struct FastEngineStats {
  std::int64_t checks = 0;            ///< particles whose hit predicate was evaluated
  std::int64_t hits = 0;              ///< wall hits
  std::int64_t rebases = 0;           ///< O(N) re-bases that started a new frame
  std::int64_t reschedules = 0;       ///< O(N) full reschedules (radius or dt changed)
  std::int64_t expired = 0;           ///< particles rescheduled because their frame expired
  std::int64_t lookahead_redone = 0;  ///< steps whose kicks exceeded the lookahead's budget
  std::int64_t parallel_steps = 0;    ///< steps whose checks ran on two threads
};

/// The counters of engine if it is a fast engine, else nothing.
std::optional<FastEngineStats> fast_engine_stats(const Engine& engine);

/// How many threads the fast engine and the pairwise forces may use: 2 by default where
/// the platform has threads and at least two cores, 1 in the browser. Results do not depend
/// on it (sums are combined in a fixed order); benchmarks set it to compare like with like.
void set_thread_limit(int threads);
int thread_limit();

}  // namespace swarm
