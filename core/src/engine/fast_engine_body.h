#pragma once
// A particle as the fast engine keeps it: the coefficients of its free oscillation about the
// CM path and its place in the schedule; and what is done to it: the wall check of Appendix A
// (against any wall: fast_engine_wall.h) and a hit's velocity jump, a re-base's shift, and its
// lab state when one is materialised.

#include <cstddef>
#include <cstdint>
#include <limits>

#include "engine/fast_engine_window.h"
#include "engine/timing_wheel.h"
#include "swarm/methods/external_forces.h"
#include "swarm/physics/floor.h"
#include "swarm/physics/system.h"
#include "swarm/physics/wall.h"

namespace swarm::fast {

/// Everything the scheduler touches for one particle, together (80 bytes): a check is then
/// one or two cache lines, fetched ahead of time (the ids due in a step are known in advance).
struct Body {
  Vec3 a, b;  ///< y_i(tau) = xc(tau) a + xs(tau) b: the free (or damped) oscillation about the CM path
  double m;
  StepIndex due;  ///< the step in whose bucket the particle waits, or kParked
  Window window;  ///< valid in the particle's anchor until its next hit; NaN: unknown
};
static_assert(sizeof(Body) == 80, "a Body should stay within 80 bytes");

/// The window of a Body that must be computed afresh.
inline constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

/// Asks the memory system for a Body before it is needed.
inline void prefetch(const Body* body) {
#if defined(__GNUC__)
  __builtin_prefetch(body);
  __builtin_prefetch(reinterpret_cast<const char*>(body) + 64);
#else
  (void)body;
#endif
}

/// WebAssembly has no prefetch instruction. Loads of every body due in a step, issued together
/// and independent of each other, overlap their cache misses in the same way (at N =
/// 1,000,000 this made the browser build's steps about twice as fast). The sum returned is
/// kept by the caller, so that the loads are not dropped.
inline double load_early(const Body* bodies, const std::uint32_t* ids, std::size_t count) {
  double touched = 0;
  for (std::size_t j = 0; j < count; ++j) {
    const Body& o = bodies[ids[j]];
    touched += o.a.x() + o.window.second;  // the first and the last cache line of the body
  }
  return touched;
}

/// y_i's velocity jumps by dv at the time of flow f0: in coefficients, the inverse flow of
/// dv. The flow's determinant xc vs - xs vc is exp(-gamma tau) under drag, and without it 1
/// only up to rounding, which for J < 0 (cosh^2 - sinh^2) is a bias of its own: dividing by its
/// computed value keeps the evaluated velocity jump dv, and the energy, unbiased. The window
/// is forgotten.
inline void kick(Body& o, const Vec3& dv, const ForcedFlow& f0, double determinant) {
  const Vec3 jump = dv / determinant;
  o.a -= f0.xs * jump;
  o.b += f0.xc * jump;
  o.window.first = kUnknown;
}

/// Sums over the particles of m |a|^2, m a.b and m |b|^2. With the flow they give the
/// particles' energy in O(1) (FastEngine::energy_at), so that the drag's loss in a step, the
/// drop of that energy, costs no pass over the particles; a hit replaces its particle's terms.
struct CoefficientSums {
  double aa = 0, ab = 0, bb = 0;

  void include(const Body& o) {
    aa += o.m * o.a.squaredNorm();
    ab += o.m * o.a.dot(o.b);
    bb += o.m * o.b.squaredNorm();
  }
  void replace(const Body& before, const Body& after) {
    aa += after.m * (after.a.squaredNorm() - before.a.squaredNorm());
    ab += after.m * (after.a.dot(after.b) - before.a.dot(before.b));
    bb += after.m * (after.b.squaredNorm() - before.b.squaredNorm());
  }
  void add(const CoefficientSums& o) {
    aa += o.aa;
    ab += o.ab;
    bb += o.bb;
  }
};

/// What every check of one step reads: the flow and the shared offset at its start and end.
struct StepData {
  ForcedFlow f0, f1;
  Vec3 o0, o0v, o1;
  double determinant;  ///< xc vs - vc xs of f0: exp(-gamma tau), 1 up to rounding without drag
};

/// Appendix A for one particle (id) and one wall: if its position predicted for the step's end
/// lies outside the wall and it is leaving the wall now, it hits now (at the step's start); the
/// wall's tally takes the hit and dv is its velocity change. Says whether it hit. The wall
/// (fast_engine_wall.h) says where it is, whether the particle leaves and what the hit does:
/// outside(r1), leaving(r0, v0), hit(m, r0, v0, id, tally) -> dv.
/// The test of the predicted position, which most checks end with, is inlined into the
/// caller's loop; the rest (reflect_leaving) is not, so that the loop stays small.
template <class Wall>
bool reflect_leaving(Body& o, std::uint32_t id, const StepData& d, const Wall& wall,
                     WallTally& tally, Vec3& dv);

template <class Wall>
inline bool reflect_if_leaving(Body& o, std::uint32_t id, const StepData& d, const Wall& wall,
                               WallTally& tally, Vec3& dv) {
  const Vec3 r1 = d.f1.xc * o.a + d.f1.xs * o.b + d.o1;
  if (!wall.outside(r1)) return false;
  return reflect_leaving(o, id, d, wall, tally, dv);
}

/// reflect_if_leaving once the particle is predicted outside: the hit if it is leaving now.
template <class Wall>
[[gnu::noinline]] bool reflect_leaving(Body& o, std::uint32_t id, const StepData& d,
                                       const Wall& wall, WallTally& tally, Vec3& dv) {
  const Vec3 r0 = d.f0.xc * o.a + d.f0.xs * o.b + d.o0;
  const Vec3 v0 = d.f0.vc * o.a + d.f0.vs * o.b + d.o0v;
  if (!wall.leaving(r0, v0)) return false;
  dv = wall.hit(o.m, r0, v0, id, tally);
  kick(o, dv, d.f0, d.determinant);  // y_i's velocity jumps by dv at the step's start
  return true;
}

/// The floor of Appendix B for one particle, after the wall's check in the same step: if its
/// position predicted for the step's end from `before` (its coefficients before this step's
/// hits: the reference engine judges both on one prediction) lies below the floor and it moves
/// down now, it bounces now (bounce_on_floor). dv is its velocity change. Says whether it bounced.
inline bool bounce_if_falling(Body& o, const Body& before, const StepData& d, const Floor& floor,
                              WallTally& tally, Vec3& dv) {
  const Vec3 r1 = d.f1.xc * before.a + d.f1.xs * before.b + d.o1;
  if (!(r1.z() < floor.z)) return false;
  const Vec3 v0 = d.f0.vc * o.a + d.f0.vs * o.b + d.o0v;
  if (!falling_through(floor, r1, v0)) return false;
  Particle p{o.m, r1, v0};
  bounce_on_floor(p, floor, tally);
  dv = p.v - v0;
  kick(o, dv, d.f0, d.determinant);
  return true;
}

/// A re-base's change of every y_i: to the oscillation about the CM from now on.
struct Shift {
  ForcedFlow f;  ///< at the re-base
  Vec3 Y, Yv;   ///< Y and its velocity then
  bool forget;  ///< also drop every window (the schedules are being rebuilt)
};

inline void shift(Body& o, const Shift& shift) {
  const ForcedFlow& f = shift.f;
  const Vec3 y = f.xc * o.a + f.xs * o.b - shift.Y;
  const Vec3 yv = f.vc * o.a + f.vs * o.b - shift.Yv;
  o.a = y;
  o.b = yv;
  // Dropped schedules are rebuilt from scratch: anchor ids are 8 bits and wrap, so after 256
  // re-bases without a wall an old window could pass for a current one.
  if (shift.forget) o.window.first = kUnknown;
}

/// The lab state of the particle at the time of flow f, o and ov being the shared offset and
/// its velocity then.
inline Particle particle_of(const Body& b, const ForcedFlow& f, const Vec3& o, const Vec3& ov) {
  return {b.m, f.xc * b.a + f.xs * b.b + o, f.vc * b.a + f.vs * b.b + ov};
}

}  // namespace swarm::fast
