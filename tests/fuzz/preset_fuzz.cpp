// libFuzzer target: any bytes through preset parsing, validation and the resource estimate, with
// the CLI's limits and the browser's. scripts/fuzz.sh builds and runs it.
//
// What must hold for every input:
// - a refusal is one short line of printable text;
// - an accepted preset survives a round trip through JSON (the UI checks its edits that way),
//   its estimate is finite, and, when it is small, its first steps stay finite.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "swarm/preset/preset.h"
#include "swarm/preset/resource_budget.h"
#include "swarm/run/side_by_side.h"

namespace {

void expect(bool ok, const char* what, const std::string& detail) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: %s\n%s\n", what, detail.c_str());
  std::abort();
}

void check(std::string_view text, const swarm::ResourceLimits& limits) {
  const swarm::PresetParse parsed = swarm::parse_preset(text, limits);
  if (!parsed.preset) {
    expect(!parsed.error.empty(), "a refusal without a message", "");
    expect(parsed.error.size() < 1000, "a message longer than 1000 bytes", parsed.error);
    for (char c : parsed.error)
      expect((unsigned char)c >= 0x20 && c != 0x7f, "a control character in a message",
             parsed.error);
    return;
  }
  const swarm::Preset& p = *parsed.preset;
  const std::string json = swarm::preset_to_json(p);
  const swarm::PresetParse again = swarm::parse_preset(json, limits);
  expect(again.preset.has_value(), "a valid preset fails its own round trip",
         again.error + "\n" + json);
  expect(swarm::preset_to_json(*again.preset) == json, "the round trip changes the preset", json);

  // Reading a preset promises that its run fits (output files are the CLI's to check when it
  // is asked for them: cli_run.cpp); both estimates must be finite.
  const swarm::ResourceEstimate e = swarm::estimate_resources(p);
  const swarm::ResourceEstimate with_files = swarm::estimate_resources(p, true);
  expect(std::isfinite(with_files.memory_bytes()) && std::isfinite(e.particle_steps) &&
             std::isfinite(e.pair_evaluations),
         "a non-finite estimate", json);
  expect(e.memory_bytes() <= limits.memory_bytes, "accepted beyond the memory limit", json);

  // Small presets: the first steps of every method must stay finite.
  if (e.particles <= 64) {
    swarm::SideBySide runs(swarm::initial_system(p), swarm::run_plan(p), p.compare);
    runs.advance(64);
    expect(runs.failure().empty(), "a valid preset's run produced a non-finite number",
           runs.failure() + "\n" + json);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check(text, swarm::ResourceLimits{});
  check(text, swarm::browser_limits());
  return 0;
}
