#include "lessons/lesson_claim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "lessons/field_rule.h"
#include "swarm/measure/confidence.h"
#include "swarm/preset/printable_text.h"

namespace swarmlab {
// Named, not anonymous: the unity build compiles this file with lesson.cpp, whose own helpers
// may share names with these.
namespace claim_reading {

using json = nlohmann::json;

constexpr std::size_t kMaxClaims = 8;
constexpr int kMaxSeeds = 64;

using field_rule::fail;
using field_rule::require;
using Invalid = field_rule::Broken;

/// Refuses keys a claim's object does not know.
void known_keys(const json& j, const std::string& path, std::initializer_list<const char*> allowed) {
  if (!j.is_object()) fail(path, "must be a JSON object");
  std::string list;
  for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
  for (const auto& item : j.items()) {
    const bool known = std::any_of(allowed.begin(), allowed.end(),
                                   [&](const char* a) { return item.key() == a; });
    if (!known) fail(path + "." + swarm::printable(item.key()), "unknown key (allowed here: " + list + ")");
  }
}

double number(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, "must be a number");
  const double x = v.get<double>();
  require(std::isfinite(x), path, "must be a finite number");
  return x;
}

bool listed_particles(const swarm::Preset& p) {
  return std::holds_alternative<std::vector<swarm::Particle>>(p.particles);
}

/// The preset with each "set" key (a dotted path, "particles.count") given its value; null
/// removes the key ("hard_spheres": null). The result obeys the preset's own rules.
swarm::Preset with_settings(const swarm::Preset& base, const json& set, const std::string& path) {
  if (!set.is_object() || set.empty())
    fail(path, "must be an object of preset keys to values, e.g. {\"hard_spheres\": null}");
  json preset = json::parse(swarm::preset_to_json(base));
  for (const auto& [key, value] : set.items()) {
    const std::string at = path + "." + swarm::printable(key);
    json* parent = &preset;
    std::size_t from = 0;
    for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', from)) {
      const std::string part = key.substr(from, dot - from);
      require(parent->contains(part) && (*parent)[part].is_object(), at,
              "\"" + swarm::printable(part) + "\" is not an object of this preset");
      parent = &(*parent)[part];
      from = dot + 1;
    }
    const std::string leaf = key.substr(from);
    require(!leaf.empty(), at, "not a preset key");
    if (value.is_null())
      parent->erase(leaf);
    else
      (*parent)[leaf] = value;
  }
  const swarm::PresetParse parsed = swarm::parse_preset(preset.dump());
  if (!parsed.preset) throw Invalid{path + ": the preset it makes: " + parsed.error};
  return *parsed.preset;
}

/// "preset" (a shipped preset's name) and "set" of a side of the comparison, on top of `base`.
ClaimRuns runs_of(const json& j, const std::string& path, const ClaimRuns& base,
                  const std::function<swarm::PresetParse(const std::string&)>& lookup) {
  ClaimRuns r = base;
  if (j.contains("preset")) {
    const json& name = j.at("preset");
    require(name.is_string(), path + ".preset", "must be a shipped preset's file name");
    r.preset_name = name.get<std::string>();
    const swarm::PresetParse parsed = lookup(r.preset_name);
    if (!parsed.preset) fail(path + ".preset", parsed.error);
    r.preset = *parsed.preset;
    r.settings.clear();
  }
  if (j.contains("set")) {
    r.preset = with_settings(r.preset, j.at("set"), path + ".set");
    r.settings = j.at("set").dump();
  }
  return r;
}

ClaimRelation relation_of(const json& j, const std::string& path) {
  const char* rule =
      "must be \"greater\", \"less\", \"equal\", \"differs\" or {\"ratio\": r} with r in [0, 1e6]";
  ClaimRelation r;
  if (j.is_string()) {
    const std::string s = j.get<std::string>();
    if (s == "greater") r.kind = ClaimRelation::Kind::greater;
    else if (s == "less") r.kind = ClaimRelation::Kind::less;
    else if (s == "equal") r.kind = ClaimRelation::Kind::equal;
    else if (s == "differs") r.kind = ClaimRelation::Kind::differs;
    else fail(path, std::string(rule) + " (not \"" + swarm::printable(s) + "\")");
    return r;
  }
  require(j.is_object() && j.size() == 1 && j.contains("ratio"), path, rule);
  r.kind = ClaimRelation::Kind::ratio;
  r.ratio = number(j.at("ratio"), path + ".ratio");
  require(r.ratio >= 0 && r.ratio <= 1e6, path + ".ratio", "must be in [0, 1e6]");
  return r;
}

/// The quantity names a side's preset can give: P and T need a container, the fits an
/// expansion.
void check_quantity(const json& j, const std::string& path, const swarm::Preset& p) {
  const std::vector<std::string>& all = claim_quantities();
  std::string list;
  for (const std::string& q : all) list += (list.empty() ? "" : ", ") + q;
  if (!j.is_string()) fail(path, "must be one of " + list);
  const std::string q = j.get<std::string>();
  require(std::find(all.begin(), all.end(), q) != all.end(), path,
          "must be one of " + list + " (not \"" + swarm::printable(q) + "\")");
  if (q == "P" || q == "T")
    require(bool(p.container_radius) && !p.expansion, path,
            "P and T are averaged at a fixed wall: the runs need a container without an expansion");
  if (q.rfind("fit.", 0) == 0)
    require(bool(p.expansion), path, "a fitted exponent needs an expansion in the runs' preset");
}

LessonClaim claim_of(const json& j, const std::string& path, const swarm::Preset& scene,
                     std::size_t options,
                     const std::function<swarm::PresetParse(const std::string&)>& lookup) {
  known_keys(j, path, {"quantity", "scene", "against", "options", "expect", "tolerance", "seeds",
                       "confidence", "seed"});
  LessonClaim c;
  c.runs.preset = scene;
  if (j.contains("scene")) {
    known_keys(j.at("scene"), path + ".scene", {"preset", "set"});
    c.runs = runs_of(j.at("scene"), path + ".scene", c.runs, lookup);
  }
  if (!j.contains("quantity")) fail(path + ".quantity", "missing (what the runs measure, e.g. \"P\")");
  check_quantity(j.at("quantity"), path + ".quantity", c.runs.preset);
  c.quantity = j.at("quantity").get<std::string>();

  if (!j.contains("against"))
    fail(path + ".against", "missing (a number, or {\"quantity\", \"preset\", \"set\"}: what a is compared with)");
  const json& against = j.at("against");
  if (against.is_number()) {
    c.against_value = number(against, path + ".against");
  } else {
    known_keys(against, path + ".against", {"quantity", "preset", "set"});
    require(!against.empty(), path + ".against",
            "must name a quantity, a preset or settings to compare with");
    c.against_quantity = c.quantity;
    const swarm::Preset* b_preset = &c.runs.preset;
    if (against.contains("preset") || against.contains("set")) {
      c.against_runs = runs_of(against, path + ".against", c.runs, lookup);
      b_preset = &c.against_runs->preset;
    }
    if (against.contains("quantity")) {
      check_quantity(against.at("quantity"), path + ".against.quantity", *b_preset);
      c.against_quantity = against.at("quantity").get<std::string>();
    } else {
      check_quantity(j.at("quantity"), path + ".against", *b_preset);
    }
    require(c.against_runs || c.against_quantity != c.quantity, path + ".against",
            "compares the quantity with itself: name another quantity, preset or settings");
  }

  if (options > 0) {
    require(!j.contains("expect"), path + ".expect",
            "a choice's claim gives \"options\": one relation per option (null where it says nothing)");
    if (!j.contains("options"))
      fail(path + ".options", "missing (one relation per option of the choice, null where it says nothing)");
    const json& list = j.at("options");
    require(list.is_array() && list.size() == options, path + ".options",
            "must give one relation per option (" + std::to_string(options) + "), null where it says nothing");
    for (std::size_t i = 0; i < list.size(); ++i)
      c.options.push_back(list[i].is_null() ? std::nullopt
                                            : std::optional(relation_of(list[i], path + ".options[" + std::to_string(i) + "]")));
    require(std::any_of(c.options.begin(), c.options.end(), [](const auto& r) { return bool(r); }),
            path + ".options", "must give a relation for at least one option");
  } else {
    require(!j.contains("options"), path + ".options",
            "only a choice's claim has options; this step's claim gives \"expect\"");
    if (!j.contains("expect"))
      fail(path + ".expect", "missing (the relation the step states: \"greater\", \"less\", ...)");
    c.expect = relation_of(j.at("expect"), path + ".expect");
  }

  if (j.contains("tolerance")) {
    c.tolerance = number(j.at("tolerance"), path + ".tolerance");
    require(c.tolerance >= 0 && c.tolerance <= 10, path + ".tolerance",
            "must be in [0, 10] (relative to |b|: 0.05 is 5%)");
  }
  if (j.contains("confidence")) {
    c.confidence = number(j.at("confidence"), path + ".confidence");
    require(c.confidence >= 0.5 && c.confidence <= 0.999, path + ".confidence",
            "must be in [0.5, 0.999] (0.95 for 95%)");
  }
  if (j.contains("seed")) {
    const json& s = j.at("seed");
    require(s.is_number_integer() && s.get<long long>() >= 0, path + ".seed",
            "must be a whole number >= 0 (the master seed)");
    c.seed = s.get<std::uint64_t>();
  }
  const bool listed = listed_particles(c.runs.preset) &&
                      (!c.against_runs || listed_particles(c.against_runs->preset));
  c.seeds = listed ? 1 : 4;
  if (j.contains("seeds")) {
    const json& s = j.at("seeds");
    require(s.is_number_integer() && s.get<long long>() >= 1 && s.get<long long>() <= kMaxSeeds,
            path + ".seeds", "must be a whole number from 1 to " + std::to_string(kMaxSeeds));
    c.seeds = int(s.get<long long>());
    if (listed)
      require(c.seeds == 1, path + ".seeds",
              "the runs list their particles, so every seed gives the same run: give 1 (or leave it out)");
    else
      require(c.seeds >= 2, path + ".seeds",
              "the runs draw their particles from a seed: give at least 2, so that the claim "
              "holds for the gas and not for one draw");
  }
  return c;
}

double mean_of(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / double(v.size());
}

}  // namespace claim_reading

const std::vector<std::string>& claim_quantities() {
  static const std::vector<std::string> names = {
      "P",        "T",      "T_kinetic",  "energy_drift", "wall_hits", "work",    "heat",
      "E_start",  "E_end",  "KE_start",   "KE_end",       "size_start", "size_end", "fit.P_V",
      "fit.T_V",  "fit.P_T"};
  return names;
}

ClaimsParse parse_claims(const std::string& json_text, const std::string& path,
                         const swarm::Preset& scene, std::size_t options,
                         const std::function<swarm::PresetParse(const std::string&)>& lookup_preset) {
  ClaimsParse out;
  try {
    const nlohmann::json list = nlohmann::json::parse(json_text);
    claim_reading::require(list.is_array() && !list.empty() && list.size() <= claim_reading::kMaxClaims, path,
            "must be a list of 1 to " + std::to_string(claim_reading::kMaxClaims) + " claims");
    for (std::size_t i = 0; i < list.size(); ++i)
      out.claims.push_back(
          claim_reading::claim_of(list[i], path + "[" + std::to_string(i) + "]", scene, options, lookup_preset));
  } catch (const claim_reading::Invalid& e) {
    out.claims.clear();
    out.error = e.message;
  } catch (const nlohmann::json::exception&) {
    out.claims.clear();
    out.error = path + ": a value of the wrong type";
  }
  return out;
}

ClaimVerdict judge(const ClaimRelation& relation, const std::vector<double>& a,
                   const std::vector<double>& b, double tolerance, double confidence,
                   ClaimMeasurement* measured) {
  ClaimMeasurement m;
  m.a = a;
  m.b = b;
  std::vector<double> d;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) d.push_back(a[k] - relation.ratio * b[k]);
  const swarm::MeanInterval ia = swarm::mean_interval(a, confidence);
  const swarm::MeanInterval ib = swarm::mean_interval(b, confidence);
  m.a_mean = ia.mean, m.a_lo = ia.lo, m.a_hi = ia.hi;
  m.b_mean = ib.mean, m.b_lo = ib.lo, m.b_hi = ib.hi;
  // Values that do not vary between the runs (a number, listed particles) have no interval:
  // they are taken as they are.
  const swarm::MeanInterval id = swarm::mean_interval(d, confidence);
  m.difference = d.empty() ? NAN : claim_reading::mean_of(d);
  m.difference_lo = id.lo ? *id.lo : m.difference;
  m.difference_hi = id.hi ? *id.hi : m.difference;
  m.margin = tolerance * std::abs(relation.ratio * ib.mean);
  if (measured) *measured = m;
  const double lo = m.difference_lo, hi = m.difference_hi, margin = m.margin;
  if (d.empty() || !std::isfinite(lo) || !std::isfinite(hi)) return ClaimVerdict::undecided;
  const bool above = lo > margin, below = hi < -margin;
  const bool within = lo >= -margin && hi <= margin;
  switch (relation.kind) {
    case ClaimRelation::Kind::greater:
      return above ? ClaimVerdict::shown : hi <= margin ? ClaimVerdict::refuted : ClaimVerdict::undecided;
    case ClaimRelation::Kind::less:
      return below ? ClaimVerdict::shown : lo >= -margin ? ClaimVerdict::refuted : ClaimVerdict::undecided;
    case ClaimRelation::Kind::equal:
    case ClaimRelation::Kind::ratio:
      return within ? ClaimVerdict::shown : above || below ? ClaimVerdict::refuted : ClaimVerdict::undecided;
    case ClaimRelation::Kind::differs:
      return above || below ? ClaimVerdict::shown : within ? ClaimVerdict::refuted : ClaimVerdict::undecided;
  }
  return ClaimVerdict::undecided;
}

std::string name_of(const ClaimRelation& relation) {
  switch (relation.kind) {
    case ClaimRelation::Kind::greater: return "greater";
    case ClaimRelation::Kind::less: return "less";
    case ClaimRelation::Kind::equal: return "equal";
    case ClaimRelation::Kind::differs: return "differs";
    case ClaimRelation::Kind::ratio: {
      char text[48];
      std::snprintf(text, sizeof text, "ratio %g", relation.ratio);
      return text;
    }
  }
  return "";
}

}  // namespace swarmlab
