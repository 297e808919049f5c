#include "ensemble/ensemble_plan.h"

#include <doctest/doctest.h>

using namespace swarmlab::ensemble;

TEST_CASE("ensemble plan: control characters and broken UTF-8 are named, printable text passes") {
  CHECK(control_character_in("/home/a b/$(x) `y`; 'q' \"dq\" ünïcödé 中文") == "");
  CHECK(control_character_in("a\nb") == "a newline (byte 2)");
  CHECK(control_character_in("ab\r") == "a carriage return (byte 3)");
  CHECK(control_character_in(std::string("a\0b", 3)) == "a NUL (byte 2)");
  CHECK(control_character_in("\x1b[31m") == "a control character (byte 1)");
  CHECK(control_character_in("a\x7f") == "a control character (byte 2)");
  CHECK(control_character_in("a\xc2\x85") == "a C1 control character (byte 2)");  // U+0085, NEL
  CHECK(control_character_in("a\xc2\xa0") == "");                                // U+00A0 is text
  CHECK(control_character_in("a\x85") == "a byte that is not UTF-8 (byte 2)");
  CHECK(control_character_in("a\xe4\xb8") == "a byte that is not UTF-8 (byte 2)");  // cut short
}

TEST_CASE("ensemble plan: the Slurm script names the folder only quoted, for bash and for sbatch") {
  EnsemblePlan plan{{{"{}", "0123456789abcdef"}}, 4, 1, 0.0, "v"};
  const std::string dir = "/x/a b's \"q\" #5 100%";
  const std::string script = slurm_array_script(plan, dir, 2);
  // bash: single quotes, each ' as '\''; sbatch: double quotes, \ before " ' #, % doubled.
  CHECK(script.find("# One run of the ensemble in '/x/a b'\\''s \"q\" #5 100%' per array task") !=
        std::string::npos);
  CHECK(script.find("#SBATCH --output=\"/x/a b\\'s \\\"q\\\" \\#5 100%%/logs/\"%a.out\n") !=
        std::string::npos);
  CHECK(script.find("mkdir -p '/x/a b'\\''s \"q\" #5 100%/logs'\n") != std::string::npos);
  CHECK(script.find("#SBATCH --array=0-3%2\n") != std::string::npos);
}

TEST_CASE("ensemble plan: a plan may hold at most 1,000,000 runs, however it is written") {
  CHECK(runs_limit_error(1000, 1000) == "");
  CHECK(runs_limit_error(2000, 1000000) ==
        "2000 points x 1000000 seeds = 2e+09 runs, more than the 1,000,000 one ensemble may hold");
  EnsemblePlan plan{std::vector<PlanPoint>(2, {"{}", "0123456789abcdef"}), 600000, 1, 0.0, "v"};
  CHECK(parse_plan(plan_json(plan)).error ==
        "points, seeds: 2 points x 600000 seeds = 1.2e+06 runs, more than the 1,000,000 one "
        "ensemble may hold");
}
