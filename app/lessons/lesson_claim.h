#pragma once
/// A claim: what a lesson step says the simulation does, in a form the program can test. A step
/// whose answer depends on the physics carries one or more ("claims"): a quantity of some runs,
/// compared with the same or another quantity of the same runs, of runs with some settings
/// changed, or with a number, by a relation (greater, less, equal within a tolerance, differs,
/// a ratio). For a choice, each option says which relation it asserts, so the physics picks
/// the right option; `swarmlab check-lesson` runs the claims and fails when it picks another
/// than the marked answer. docs/lessons.md, "How to write a claim", documents the fields.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "swarm/preset/preset.h"

namespace swarmlab {

/// How the claim's quantity a compares with b: a > b, a < b, a = b, a != b (each beyond or
/// within the claim's relative tolerance of b), or a = ratio b.
struct ClaimRelation {
  enum class Kind { greater, less, equal, differs, ratio };
  Kind kind = Kind::equal;
  double ratio = 1;  ///< b's factor: 1 but for Kind::ratio
};

/// One side of a comparison: a preset (the step's scene, or a shipped one, with some of its
/// keys set) run from `seeds` seeds.
struct ClaimRuns {
  std::string preset_name;  ///< "" for the step's scene
  swarm::Preset preset;     ///< with the claim's settings applied
  std::string settings;     ///< the "set" object as written, "" when none (for the report)
};

struct LessonClaim {
  std::string quantity;  ///< one of claim_quantities()
  ClaimRuns runs;        ///< a
  /// b: a number, or a quantity (the same or another) of the same runs or of other runs.
  std::optional<double> against_value;
  std::string against_quantity;
  std::optional<ClaimRuns> against_runs;  ///< none: the same runs as a (paired values)
  /// A choice step: one relation per option (none where the option says nothing this claim
  /// measures). Any other step: `expect`, the relation its text or outcome states.
  std::vector<std::optional<ClaimRelation>> options;
  std::optional<ClaimRelation> expect;
  double tolerance = 0.05;  ///< relative to |b|
  double confidence = 0.95;
  int seeds = 4;          ///< runs per side; 1 for listed particles (every run is the same)
  std::uint64_t seed = 1;  ///< master seed: run k starts from swarm::run_seed(seed, k)
};

/// The quantities a claim can name: the ensemble record's time averages and books (P, T,
/// energy_drift, wall_hits, work, heat, fit.P_V, fit.T_V, fit.P_T), the run's first and last
/// sample (E_start, E_end, KE_start, KE_end, size_start, size_end) and T_kinetic = (2/3) KE / N
/// in the CM frame (over the wall's window where the record has one: a container, no
/// expansion; else at the end), which
/// the wall's T equals only for Maxwellian speeds.
const std::vector<std::string>& claim_quantities();

struct ClaimsParse {
  std::vector<LessonClaim> claims;
  std::string error;  ///< "" or "steps[4].claims[0].relation: ..." naming the field and the rule
};

/// Reads a step's "claims" (the JSON text of the list) against the step's scene. `options` is
/// the step's choice options (0 when the step has no choice task); `lookup_preset` finds a
/// shipped preset by file name, as for a step's "preset" ("" and the preset, or why not).
ClaimsParse parse_claims(const std::string& json_text, const std::string& path,
                         const swarm::Preset& scene, std::size_t options,
                         const std::function<swarm::PresetParse(const std::string&)>& lookup_preset);

/// What the runs showed about one relation: shown, refuted, or undecided at the confidence.
enum class ClaimVerdict { shown, refuted, undecided };

/// a and b per run, paired (run k of each side shares its seed), and what they show.
struct ClaimMeasurement {
  std::vector<double> a, b;
  double a_mean = 0, b_mean = 0;
  std::optional<double> a_lo, a_hi, b_lo, b_hi;  ///< their intervals (none for one run)
  /// a - r b, per run: its mean and interval, for the relation's r.
  double difference = 0;
  double difference_lo = 0, difference_hi = 0;
  double margin = 0;  ///< tolerance x |r b|
};

/// Judges a relation on paired values a[k], b[k] at the claim's tolerance and confidence: the
/// interval of the mean of a - r b against the margin tolerance |r mean(b)|. One pair (a
/// deterministic run) is judged on its value.
ClaimVerdict judge(const ClaimRelation& relation, const std::vector<double>& a,
                   const std::vector<double>& b, double tolerance, double confidence,
                   ClaimMeasurement* measured = nullptr);

/// The relation as a lesson writes it: "greater", "less", "equal", "differs", {"ratio": r}.
std::string name_of(const ClaimRelation& relation);

}  // namespace swarmlab
