#pragma once
// What made an output: the program's version (its commit, and whether the tree it was built
// from had uncommitted changes), the compiler, the host, the date and the seeds. Every file
// swarmlab writes with numbers in it carries this, as JSON ("provenance") in JSON outputs and
// as text lines in CSV comments and SVG metadata, so that a figure or a report found later
// says which build, machine and seeds gave it.
//
// The host is the operating system (name and release) and the machine's architecture, never
// its network name: the name identifies a person's computer (often their own name) in files
// that are shared, and adds nothing to reproducing a number. In the browser it is "browser".

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "swarm/preset/preset.h"

namespace swarmlab::report {

/// The seeds an output's numbers were drawn from.
struct Seeds {
  /// One run: the seed its particles were drawn from (the preset's particles.seed, or an
  /// ensemble run's). None for listed particles, which need no seed.
  std::optional<std::uint64_t> seed{};
  /// An ensemble: its master seed; run k of each point starts from run_seed(base, k).
  std::optional<std::uint64_t> base{};
  long runs = 0;  ///< with base: the runs per point (k = 0 .. runs - 1)
};

/// The preset's seed when it draws its particles (a generated swarm), else none.
Seeds seeds_of(const swarm::Preset& preset);

struct Provenance {
  std::string version;       ///< `swarmlab --version`: the commit, "-dirty-" and a hash of the changes
  std::string commit;        ///< the commit alone ("unknown" outside a git checkout)
  std::optional<bool> clean; ///< no uncommitted changes; none when the commit is unknown
  std::string compiler;      ///< e.g. "GCC 12.2.0", "clang 14.0.6", "Emscripten 3.1.6 (clang ...)"
  std::string os;            ///< e.g. "Linux 6.1.0-18-amd64", "browser", "node"
  std::string machine;       ///< e.g. "x86_64", "wasm32"
  std::string date;          ///< UTC, ISO 8601 to the second: "2026-12-07T18:40:12Z"
  Seeds seeds;
};

/// This program, here and now, with the seeds given.
Provenance provenance_now(const Seeds& seeds);

/// {"program": "swarmlab", "version", "commit", "clean" (true, false or null), "compiler",
///  "host": {"os", "machine"}, "date", "seeds": {"seed"} or {"base", "runs"} or {}}.
nlohmann::json provenance_json(const Provenance& p);
/// The object provenance_json writes, read back; none and a message naming the key otherwise.
std::optional<Provenance> provenance_from_json(const nlohmann::json& j, std::string& error);

/// The same as lines of plain text without line breaks, the first "made by swarmlab VERSION
/// from commit C with a clean tree" (or "with uncommitted changes"), then "compiler: ...",
/// "host: OS MACHINE", "date: ..." and "seeds: ...".
std::vector<std::string> provenance_lines(const Provenance& p);
/// Each line behind "# ", for the top of a CSV file (readers skip them as comments:
/// pandas.read_csv(comment="#"), or Python's csv after dropping lines that start with '#').
/// A comma, semicolon, tab or double quote in a line becomes a space: a spreadsheet that
/// does not skip comments then reads each line as one cell of text starting with '#', never
/// as several cells, one of which could start with '=' (csv_field.h's rule, for comments).
std::string csv_comment_lines(const std::vector<std::string>& lines);

}  // namespace swarmlab::report
