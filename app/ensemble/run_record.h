#pragma once
// One run of an ensemble, written whole to DIR/runs/<k>.json by `swarmlab run --record` (and by
// `swarmlab ensemble`): who it is (index, seed, preset hash, program version), the numbers the
// merge compares across runs, each with its within-run error where it has one, and the wall's
// P(t), T(t), T kinetic(t) and the stages for the merge's bands. Small and of one size whatever the run's
// length, so that a merge of thousands of runs reads little. Sealed by a SHA-256 digest of all
// of this (record_digest): a record edited by hand or damaged is refused like a cut one. The
// digest catches a change, it does not prove who wrote the record (anyone with swarmlab or
// the rule below can seal a record).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "report/provenance.h"
#include "swarm/run/run.h"

namespace swarmlab::ensemble {

inline constexpr const char* kRunFormat = "swarmlab ensemble run";
inline constexpr int kRunFormatVersion = 4;  ///< 2: the digest; 3: the provenance; 4: T kinetic
/// The P(t), T(t) series hold at most this many points, each the wall average of a stretch
/// of consecutive samples (exact: impulses and hits add up).
inline constexpr std::size_t kSeriesPoints = 200;

/// A number one run gives, and when it is a time average (P, T) its standard error about this
/// run's own long-run value (swarm::wall_estimate over the averaging window: from the
/// window's parts), none where the window is too short to measure one.
struct RunValue {
  double value = 0;
  std::optional<double> se;
};

struct RunIdentity {
  long index = 0;
  std::uint64_t seed = 0;
  std::string preset_hash;
  std::string version;  ///< swarmlab's, which decides the bits
  double perturbation = 0;
};

struct RunRecord {
  RunIdentity id;
  /// Who ran it, where and when (its seeds: {id.seed}); inside the digest, so that an edited
  /// record cannot pass for one made elsewhere or at another time.
  report::Provenance made_by;
  std::string failure;  ///< "" for a finished run; the reason a run stopped otherwise
  double equilibration_start = 0;  ///< time from which P and T are averaged
  /// "P", "T" (time averages after the equilibration start), "T_kinetic" ((2/3) KE / N in
  /// the CM frame, averaged over the samples of the same window), "energy_drift", "wall_hits",
  /// with outside work or heat (EngineConfig::exchanges_energy) "work", "heat" (the books
  /// at the end), "KE_start" and "KE_end",
  /// and for expansions "stage<k>.P", "stage<k>.T" (k from 1), "fit.P_V", "fit.T_V",
  /// "fit.P_T" (each run's fitted exponent) and "r2.P_V", "r2.T_V", "r2.P_T" (their R^2),
  /// and where the virial balance applies (swarm::virial_balance_applies) its terms over P's
  /// window: "virial.3PV", "virial.2KE-2U", "virial.G_start", "virial.G_end",
  /// "virial.imbalance" (-(G_end - G_start) / the window; se: its error), "virial.residual"
  /// (3PV - (2KE - 2U) - imbalance: the collision scheme's offset), "virial.relative_imbalance"
  /// (over 3PV: how far P is off) and "virial.holds" (1, or 0: the run is too short to claim
  /// equilibrium).
  std::map<std::string, RunValue> values;
  /// The wall series, at most kSeriesPoints; T is NAN (null in the file) where nothing hit.
  /// T_kinetic: the mean of the samples' (2/3) KE / N that end each stretch's intervals.
  std::vector<double> t, P, T, R, T_kinetic;
  /// Expansions: one per stage; T is NAN (null in the file) for a stage without hits;
  /// T_kinetic is the stage's (swarm::Stage::T_kinetic).
  std::vector<double> stage_V, stage_P, stage_T, stage_T_kinetic;
};

/// The record of a finished (or failed) run, made here and now.
RunRecord record_of(const RunIdentity& id, swarm::Run& run);
std::string record_json(const RunRecord& r);

/// The canonical text the digest is taken over: independent of how the JSON is laid out, so
/// only a change of a value changes it. One line per item, each ending in "\n", in this order:
///   swarmlab ensemble run 4
///   swarmlab TEXT / preset_hash TEXT / index INT / seed INT / perturbation NUM /
///   failure TEXT / equilibration_start NUM
///   provenance TEXT TEXT CLEAN TEXT TEXT TEXT TEXT   (version, commit, clean, compiler,
///   host.os, host.machine, date; CLEAN is true, false or null)
///   provenance.seeds INT-or-- INT-or-- INT   (seeds.seed, seeds.base, seeds.runs or 0)
///   value TEXT NUM NUM-or--   (each of "values": name, value, se; names in byte order)
///   series.t LIST / series.P LIST / series.T LIST / series.R LIST / series.T_kinetic LIST /
///   stages.V LIST / stages.P LIST / stages.T LIST / stages.T_kinetic LIST
/// where TEXT is the byte count, ':' and the bytes (so any text is unambiguous), INT is
/// decimal, NUM is C's printf("%.17g") of the double (which reads back to the same double)
/// or "null" for a number that is not finite (JSON's null), and LIST is the count followed by
/// " NUM" per element. Items on one line are separated by one space.
std::string canonical_text(const RunRecord& r);
/// "sha256:" and the SHA-256 (64 lowercase hex digits) of canonical_text(r): the record's
/// "digest".
std::string record_digest(const RunRecord& r);

struct RecordRead {
  std::optional<RunRecord> record;
  std::string error;  ///< what is wrong with the text, naming the key
};
RecordRead parse_record(const std::string& text);

}  // namespace swarmlab::ensemble
