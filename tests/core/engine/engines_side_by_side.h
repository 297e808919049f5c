#pragma once
// The reference and the fast engine run side by side from one state: what both engine test
// files require of every wall and force the fast engine runs.

#include <doctest/doctest.h>

#include <cmath>
#include <functional>

#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/gravity.h"
#include "test_systems.h"

namespace swarm::testing {

/// What changes a run on the way, applied to both engines alike before step `step`.
using Intervention = std::function<void(int step, Engine& engine)>;

/// The energy the books count: kinetic, the springs' and gravity's.
inline double booked_energy(const System& s, const EngineConfig& config) {
  return total_energy(s) + gravity_potential_energy(s, config.forces.gravity);
}

/// What a side-by-side run saw, from the fast engine (the reference's is required equal).
struct SideBySideRun {
  long hits = 0, floor_hits = 0;
  EnergyBooks books;
  FastEngineStats stats;
};

/// Runs both engines under config (walls, forces, floor) and requires the same wall and floor
/// hits in every step, the same wall impulse, time, wall radius and final state (1e-9), the
/// same books, and books that balance in each engine: the energy from outside (the wall's work
/// and heat, less the drag's loss) is the change of the energy, gravity's potential included.
inline SideBySideRun require_same_run(const System& s, const EngineConfig& config, double dt,
                                      int steps, const Intervention& intervene = {}) {
  REQUIRE(fast_engine_applies(config));
  auto reference = make_reference_engine(s, config);
  auto fast = make_fast_engine(s, config);
  SideBySideRun run;
  EnergyBooks books_ref;
  double impulse_ref = 0, impulse_fast = 0;
  for (int i = 0; i < steps; ++i) {
    if (intervene) {
      intervene(i, *reference);
      intervene(i, *fast);
    }
    const WallTally a = reference->step(dt), b = fast->step(dt);
    CAPTURE(i);
    REQUIRE(a.hits == b.hits);
    REQUIRE(a.floor_hits == b.floor_hits);
    run.hits += b.hits;
    run.floor_hits += b.floor_hits;
    impulse_ref += a.radial_impulse;
    impulse_fast += b.radial_impulse;
    books_ref.add(a.books);
    run.books.add(b.books);
  }
  CHECK(impulse_fast == doctest::Approx(impulse_ref).epsilon(1e-12));
  CHECK(fast->time() == reference->time());
  CHECK(fast->container_radius() == reference->container_radius());
  CHECK(max_state_difference(reference->system(), fast->system()) < 1e-9);

  const double E0 = booked_energy(s, config);
  const double scale = kinetic_energy(s) + std::abs(E0) + std::abs(books_ref.wall_work) +
                       std::abs(books_ref.wall_heat) + books_ref.drag_loss;
  CHECK(std::abs(run.books.net() - books_ref.net()) < 1e-10 * scale);
  CHECK(std::abs(run.books.drag_loss - books_ref.drag_loss) < 1e-10 * scale);
  CHECK(std::abs(booked_energy(reference->system(), config) - E0 - books_ref.net()) <
        1e-10 * scale);
  CHECK(std::abs(booked_energy(fast->system(), config) - E0 - run.books.net()) < 1e-10 * scale);
  if (config.forces.drag) CHECK(run.books.drag_loss > 1e-3 * scale);
  run.stats = *fast_engine_stats(*fast);
  return run;
}

}  // namespace swarm::testing
