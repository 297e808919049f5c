#pragma once
// A sweep: one base preset, some of its keys given several values (a grid, every combination,
// or a list of points), and the runs per point. SWEEP.json:
//   {"preset": "base.json", "grid": {"J": [0.5, 1, 2], "particles.count": [1000, 4000]},
//    "seeds": 16}
// or "points": [{"J": 0.5}, {"J": 1, "particles.count": 2000}] instead of "grid". A key names
// a value of the base preset by its path ("container.radius", "expansion.factor") and must be
// in the base preset; each point's preset is checked by the preset's own rules.

#include <optional>
#include <string>
#include <vector>

#include "swarm/preset/preset.h"

namespace swarmlab::ensemble {

struct SweepPoint {
  std::string values;  ///< the point's key values, a JSON object as text
  swarm::Preset preset;
};

struct Sweep {
  std::vector<SweepPoint> points;  ///< a grid's in key order, the last key changing fastest
  std::optional<long> seeds;       ///< the file's "seeds", if it gives them
};

struct SweepRead {
  std::optional<Sweep> sweep;
  std::string error;  ///< names the key and the rule, as a preset's errors do
};

/// Whether a file's text is a sweep (an object with "preset" and "grid" or "points") rather
/// than a preset.
bool is_sweep(const std::string& text);

/// Reads a sweep; `sweep_path` resolves its "preset" (relative to the sweep file's folder).
SweepRead read_sweep(const std::string& text, const std::string& sweep_path);

}  // namespace swarmlab::ensemble
