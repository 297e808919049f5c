#include "lessons/lesson_claim.h"

#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "lessons/lesson.h"

using namespace swarmlab;

namespace {

using ojson = nlohmann::ordered_json;

const char* kClaimPair = R"({"J": 1.0, "particles": [{"m": 1, "r": [0.5, 0, 0], "v": [0, 0.7, 0]},
  {"m": 1, "r": [-0.5, 0, 0], "v": [0, -0.7, 0]}], "dt": 0.01, "duration": 5})";
const char* kClaimGas = R"({"J": 0.0, "particles": {"count": 50, "position_radius": 0.9,
  "velocity": {"speed": 1}}, "container": {"radius": 1}, "hard_spheres": {"radius": 0.02},
  "dt": 0.01, "duration": 5})";

swarm::PresetParse claim_test_lookup(const std::string& name) {
  if (name == "pair.json") return swarm::parse_preset(kClaimPair);
  if (name == "gas.json") return swarm::parse_preset(kClaimGas);
  return {std::nullopt, "no shipped preset \"" + name + "\""};
}

/// A lesson of two steps on the gas: a choice with `claim` on step 1, a text with `expect_claim`
/// on step 0 (none when null).
ojson claim_lesson_with(const ojson& claim, const ojson& expect_claim = nullptr) {
  ojson l = ojson::parse(R"({"lesson": 1, "id": "t", "title": "T", "summary": "S", "steps": [
    {"text": "Watch.", "preset": "gas.json"},
    {"text": "Pick.", "task": {"kind": "choice", "prompt": "P is", "options": ["higher", "the same", "lower"],
     "answer": 0}}]})");
  if (!claim.is_null()) l["steps"][1]["claims"] = ojson::array({claim});
  if (!expect_claim.is_null()) l["steps"][0]["claims"] = ojson::array({expect_claim});
  return l;
}

ojson good_claim_json() {
  return ojson::parse(R"({"quantity": "P", "against": {"set": {"hard_spheres": null}},
    "options": ["greater", "equal", "less"], "tolerance": 0.1, "seeds": 3})");
}

std::string claim_error_of(const ojson& lesson) {
  const LessonParse parsed = parse_lesson(lesson.dump(), claim_test_lookup);
  return parsed.lesson ? std::string() : parsed.error;
}

}  // namespace

TEST_CASE("a claim reads into its quantity, its two sides and one relation per option") {
  const LessonParse parsed = parse_lesson(claim_lesson_with(good_claim_json()).dump(), claim_test_lookup);
  REQUIRE_MESSAGE(parsed.lesson, parsed.error);
  REQUIRE(parsed.lesson->steps[1].claims.size() == 1);
  const LessonClaim& c = parsed.lesson->steps[1].claims[0];
  CHECK(c.quantity == "P");
  CHECK(c.against_quantity == "P");
  REQUIRE(c.against_runs);
  CHECK(c.runs.preset.sphere_radius);        // the scene: hard spheres
  CHECK(!c.against_runs->preset.sphere_radius);  // against: the same gas without them
  CHECK(c.against_runs->preset.dt == c.runs.preset.dt);
  REQUIRE(c.options.size() == 3);
  CHECK(c.options[0]->kind == ClaimRelation::Kind::greater);
  CHECK(c.seeds == 3);
  CHECK(c.tolerance == 0.1);
  CHECK(c.confidence == 0.95);
}

TEST_CASE("a bad claim is refused with the field and the rule") {
  auto with = [](const char* key, const ojson& value) {
    ojson c = good_claim_json();
    if (value.is_null()) c.erase(key);
    else c[key] = value;
    return claim_error_of(claim_lesson_with(c));
  };
  CHECK(with("quantity", "Q").find("steps[1].claims[0].quantity: must be one of P, T,") == 0);
  CHECK(with("quantity", nullptr) == "steps[1].claims[0].quantity: missing (what the runs measure, e.g. \"P\")");
  CHECK(with("options", ojson::array({"greater", "equal"})) ==
        "steps[1].claims[0].options: must give one relation per option (3), null where it says nothing");
  CHECK(with("options", ojson::array({nullptr, nullptr, nullptr})) ==
        "steps[1].claims[0].options: must give a relation for at least one option");
  CHECK(with("options", ojson::array({"bigger", nullptr, nullptr})).find(
            "steps[1].claims[0].options[0]: must be \"greater\", \"less\", \"equal\", \"differs\" or "
            "{\"ratio\": r} with r in [0, 1e6] (not \"bigger\")") == 0);
  CHECK(with("options", ojson::array({ojson{{"ratio", -1}}, nullptr, nullptr})) ==
        "steps[1].claims[0].options[0].ratio: must be in [0, 1e6]");
  CHECK(with("seeds", 1) ==
        "steps[1].claims[0].seeds: the runs draw their particles from a seed: give at least 2, so "
        "that the claim holds for the gas and not for one draw");
  CHECK(with("seeds", 65) == "steps[1].claims[0].seeds: must be a whole number from 1 to 64");
  CHECK(with("tolerance", -0.1) ==
        "steps[1].claims[0].tolerance: must be in [0, 10] (relative to |b|: 0.05 is 5%)");
  CHECK(with("confidence", 1) == "steps[1].claims[0].confidence: must be in [0.5, 0.999] (0.95 for 95%)");
  CHECK(with("against", nullptr).find("steps[1].claims[0].against: missing") == 0);
  CHECK(with("against", ojson::object()) ==
        "steps[1].claims[0].against: must name a quantity, a preset or settings to compare with");
  CHECK(with("against", ojson{{"quantity", "P"}}) ==
        "steps[1].claims[0].against: compares the quantity with itself: name another quantity, "
        "preset or settings");
  CHECK(with("against", ojson{{"set", {{"partikles", 10}}}}).find(
            "steps[1].claims[0].against.set: the preset it makes: partikles: unknown key") == 0);
  CHECK(with("against", ojson{{"set", {{"dt", -1}}}}) ==
        "steps[1].claims[0].against.set: the preset it makes: dt: must be > 0");
  CHECK(with("against", ojson{{"set", {{"nope.count", 10}}}}) ==
        "steps[1].claims[0].against.set.nope.count: \"nope\" is not an object of this preset");
  CHECK(with("against", ojson{{"preset", "fig9.json"}}) ==
        "steps[1].claims[0].against.preset: no shipped preset \"fig9.json\"");
  CHECK(with("against", ojson{{"set", {{"container", nullptr}}}}) ==
        "steps[1].claims[0].against: P and T are averaged at a fixed wall: the runs need a "
        "container without an expansion");
  CHECK(with("expect", "greater") ==
        "steps[1].claims[0].expect: a choice's claim gives \"options\": one relation per option "
        "(null where it says nothing)");
  CHECK(with("wish", 1).find("steps[1].claims[0].wish: unknown key") == 0);
  CHECK(claim_error_of(claim_lesson_with(nullptr, ojson::parse(R"({"quantity": "P", "against": 90,
    "options": ["greater", "less"]})"))) ==
        "steps[0].claims[0].options: only a choice's claim has options; this step's claim gives \"expect\"");
  CHECK(claim_error_of(claim_lesson_with(nullptr, ojson::parse(R"({"quantity": "fit.P_V", "against": 0,
    "expect": "less"})"))) ==
        "steps[0].claims[0].quantity: a fitted exponent needs an expansion in the runs' preset");
  // Listed particles run the same whatever the seed: one run is the claim's.
  ojson pair = claim_lesson_with(nullptr, ojson::parse(R"({"quantity": "E_end",
    "scene": {"preset": "pair.json"}, "against": {"quantity": "E_start"}, "expect": "equal", "seeds": 3})"));
  CHECK(claim_error_of(pair) ==
        "steps[0].claims[0].seeds: the runs list their particles, so every seed gives the same run: "
        "give 1 (or leave it out)");
  pair["steps"][0]["claims"][0].erase("seeds");
  const LessonParse parsed = parse_lesson(pair.dump(), claim_test_lookup);
  REQUIRE_MESSAGE(parsed.lesson, parsed.error);
  CHECK(parsed.lesson->steps[0].claims[0].seeds == 1);
}

// The verdicts against intervals worked out by hand: values 1, 2, 3 have mean 2, sd 1, se
// 1/sqrt(3) and t(0.975, 2) = 4.3027, so the 95 % interval of their mean is 2 +- 2.4841.
TEST_CASE("judge: a relation is shown, refuted or undecided by the interval of a - r b") {
  const std::vector<double> a = {11, 12, 13}, b = {10, 10, 10};
  ClaimMeasurement m;
  const ClaimRelation greater{ClaimRelation::Kind::greater, 1};
  // a - b = 1, 2, 3: [-0.484, 4.484]; with no margin neither side is certain.
  CHECK(judge(greater, a, b, 0, 0.95, &m) == ClaimVerdict::undecided);
  CHECK(m.difference == doctest::Approx(2));
  CHECK(m.difference_lo == doctest::Approx(2 - 4.302653 / std::sqrt(3.0)).epsilon(1e-5));
  CHECK(m.difference_hi == doctest::Approx(2 + 4.302653 / std::sqrt(3.0)).epsilon(1e-5));
  // At 50 % the t quantile is 0.8165 (two degrees of freedom): [1.529, 2.471] > 0.
  CHECK(judge(greater, a, b, 0, 0.5) == ClaimVerdict::shown);
  CHECK(judge(ClaimRelation{ClaimRelation::Kind::less, 1}, a, b, 0, 0.5) == ClaimVerdict::refuted);
  CHECK(judge(ClaimRelation{ClaimRelation::Kind::differs, 1}, a, b, 0, 0.5) == ClaimVerdict::shown);
  CHECK(judge(ClaimRelation{ClaimRelation::Kind::equal, 1}, a, b, 0, 0.5) == ClaimVerdict::refuted);
  // A margin of 50 % of b (5) holds the whole 95 % interval: equal, and not greater.
  CHECK(judge(ClaimRelation{ClaimRelation::Kind::equal, 1}, a, b, 0.5, 0.95) == ClaimVerdict::shown);
  CHECK(judge(greater, a, b, 0.5, 0.95) == ClaimVerdict::refuted);
  CHECK(judge(ClaimRelation{ClaimRelation::Kind::differs, 1}, a, b, 0.5, 0.95) == ClaimVerdict::refuted);
  // a = 1.2 b within 1 %: a - 1.2 b = -1, 0, 1, interval 0 +- 2.48, margin 0.12: undecided.
  const ClaimRelation ratio{ClaimRelation::Kind::ratio, 1.2};
  CHECK(judge(ratio, a, b, 0.01, 0.95, &m) == ClaimVerdict::undecided);
  CHECK(m.margin == doctest::Approx(0.12));
  // One pair (a run that is the same every time) is judged on its value.
  CHECK(judge(ratio, {12}, {10}, 0.01, 0.95) == ClaimVerdict::shown);
  CHECK(judge(ratio, {12.5}, {10}, 0.01, 0.95) == ClaimVerdict::refuted);
  CHECK(judge(greater, {12}, {10}, 0.1, 0.95) == ClaimVerdict::shown);
  CHECK(judge(greater, {10.5}, {10}, 0.1, 0.95) == ClaimVerdict::refuted);
  // Against a number b = 0 the margin is 0: a strictly above it is greater.
  CHECK(judge(greater, {1e-9}, {0}, 0.5, 0.95) == ClaimVerdict::shown);
  CHECK(judge(ClaimRelation{ClaimRelation::Kind::equal, 1}, {0}, {0}, 0.5, 0.95) == ClaimVerdict::shown);
}
