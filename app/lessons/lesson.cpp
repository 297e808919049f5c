#include "lessons/lesson.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "i18n/language.h"
#include "i18n/printed.h"
#include "i18n/translator.h"
#include "lessons/device_words.h"
#include "lessons/field_rule.h"
#include "swarm/preset/printable_text.h"
#include "swarm/preset/strict_json.h"

namespace swarmlab {
namespace {

using json = nlohmann::json;

constexpr std::size_t kMaxSteps = 100;
constexpr std::size_t kMaxTextBytes = 8000;
constexpr std::size_t kMaxTitleBytes = 120;
constexpr std::size_t kMaxIdBytes = 64;
constexpr std::size_t kMaxOptions = 8;
/// A step's run may be continued to at most this time (a class period at any speed).
constexpr double kMaxRunUntil = 1e6;

using field_rule::fail;
using field_rule::require;
using Invalid = field_rule::Broken;

std::string format(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

/// A translated sentence with its values, numbers in the language's decimal separator.
std::string sentence(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::string text = vprinted(format, args);
  va_end(args);
  return translator().numbers(text);
}

/// One JSON object of the lesson, refusing keys it does not know.
class Fields {
 public:
  Fields(const json& j, std::string path, std::initializer_list<const char*> allowed)
      : j_(j), path_(std::move(path)) {
    if (!j.is_object()) fail(path_.empty() ? "lesson" : path_, "must be a JSON object");
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    for (const auto& item : j.items()) {
      bool known = false;
      for (const char* a : allowed) known = known || item.key() == a;
      if (!known)
        fail(join(swarm::printable(item.key())), "unknown key (allowed here: " + list + ")");
    }
  }

  bool has(const char* key) const { return j_.contains(key) && !j_.at(key).is_null(); }
  const json& at(const char* key) const { return j_.at(key); }
  std::string path(const char* key) const { return join(key); }

  /// A string of 1 to max_bytes bytes; `what` says what it is for the missing message.
  std::string text(const char* key, std::size_t max_bytes, const char* what) const {
    if (!has(key)) fail(path(key), std::string("missing (") + what + ")");
    if (!at(key).is_string()) fail(path(key), "must be a string");
    std::string s = at(key).get<std::string>();
    require(!s.empty(), path(key), "must not be empty");
    require(s.size() <= max_bytes, path(key),
            "must be at most " + std::to_string(max_bytes) + " bytes long");
    return s;
  }
  std::size_t index(const char* key, std::size_t below, const std::string& rule) const {
    const json& v = at(key);
    if (!v.is_number_integer() || v.get<long long>() < 0)
      fail(path(key), "must be a whole number >= 0");
    const auto x = v.get<unsigned long long>();
    require(x < below, path(key), rule);
    return std::size_t(x);
  }
  double number(const char* key) const {
    if (!at(key).is_number()) fail(path(key), "must be a number");
    const double x = at(key).get<double>();
    require(std::isfinite(x), path(key), "must be a finite number");
    return x;
  }

 private:
  std::string join(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  const json& j_;
  std::string path_;
};

/// The code point of the UTF-8 character at text[i], moving i past it. Text from the JSON parser
/// is valid UTF-8 (nlohmann refuses anything else).
char32_t next_code_point(const std::string& text, std::size_t& i) {
  const unsigned char lead = static_cast<unsigned char>(text[i++]);
  if (lead < 0x80) return lead;
  const int extra = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : 1;
  char32_t c = lead & (0x3F >> extra);
  for (int k = 0; k < extra && i < text.size(); ++k)
    c = (c << 6) | (static_cast<unsigned char>(text[i++]) & 0x3F);
  return c;
}

/// Spaces of every width, and line breaks.
bool is_space(char32_t c) {
  return c == ' ' || c == '\n' || c == 0xA0 || c == 0x1680 || (c >= 0x2000 && c <= 0x200A) ||
         c == 0x2028 || c == 0x2029 || c == 0x202F || c == 0x205F || c == 0x3000;
}

/// Characters that draw nothing: spaces, direction marks and embeddings (U+200E/F,
/// U+202A..E, U+2066..9, U+061C), zero-width characters (U+200B..D, U+2060, U+FEFF), the soft
/// hyphen, invisible operators, tags and the Hangul fillers. A text of only these shows as a
/// blank title, button or option.
bool draws_nothing(char32_t c) {
  return is_space(c) || c == 0xAD || c == 0x34F || c == 0x61C || c == 0x115F || c == 0x1160 ||
         c == 0x180E || (c >= 0x200B && c <= 0x200F) || (c >= 0x202A && c <= 0x202E) ||
         (c >= 0x2060 && c <= 0x206F) || c == 0x3164 || c == 0xFEFF || c == 0xFFA0 ||
         (c >= 0xE0000 && c <= 0xE007F);
}

std::string code_name(char32_t c) {
  char code[12];
  std::snprintf(code, sizeof code, "U+%04X", unsigned(c));
  return code;
}

/// Lesson text: something to see, no control characters but line breaks (C0, DEL and the C1
/// controls U+0080..U+009F alike), and every *emphasis* closed within its paragraph.
void check_prose(const std::string& text, const std::string& path) {
  std::size_t stars = 0;
  std::optional<char32_t> invisible;  // the first character that draws nothing but is no space
  bool visible = false;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t at = i;
    const char32_t c = next_code_point(text, i);
    if ((c < 0x20 && c != '\n') || (c >= 0x7F && c <= 0x9F))
      fail(path, "control character " + code_name(c) + " (only line breaks are allowed)");
    if (!draws_nothing(c))
      visible = true;
    else if (!is_space(c) && !invisible)
      invisible = c;
    if (c == '*') ++stars;
    const bool paragraph_end = i == text.size() || text.compare(at, 2, "\n\n") == 0;
    if (paragraph_end && stars % 2 != 0)
      fail(path, "an emphasis is not closed in its paragraph (write *like this*)");
    if (paragraph_end) stars = 0;
  }
  if (!visible)
    fail(path, "must show something (it holds only spaces" +
                   (invisible ? " or invisible characters such as " + code_name(*invisible) : "") +
                   ")");
  if (const std::string problem = device_words_problem(text); !problem.empty()) fail(path, problem);
}

/// How many alternatives each {a|b} choice of the text holds, in order.
std::vector<std::size_t> device_choices(const std::string& text) {
  std::vector<std::size_t> out;
  for (std::size_t open = text.find('{'); open != std::string::npos; open = text.find('{', open + 1)) {
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) break;
    out.push_back(std::size_t(std::count(text.begin() + long(open), text.begin() + long(close), '|')) + 1);
  }
  return out;
}

std::vector<std::string> option_list(const Fields& f, const char* key) {
  if (!f.has(key)) fail(f.path(key), "missing (a list of 2 to 8 strings is required)");
  const json& list = f.at(key);
  require(list.is_array() && list.size() >= 2 && list.size() <= kMaxOptions, f.path(key),
          "must be a list of 2 to 8 strings");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = f.path(key) + "[" + std::to_string(i) + "]";
    require(list[i].is_string() && !list[i].get<std::string>().empty(), path,
            "must be a non-empty string");
    out.push_back(list[i].get<std::string>());
    require(out.back().size() <= kMaxTextBytes, path,
            "must be at most " + std::to_string(kMaxTextBytes) + " bytes long");
    check_prose(out.back(), path);
  }
  return out;
}

template <typename Enum, std::size_t n>
Enum named(const Fields& f, const char* key, const Enum (&values)[n]) {
  std::string list;
  for (Enum v : values) list += (list.empty() ? "\"" : ", \"") + std::string(name_of(v)) + "\"";
  if (!f.at(key).is_string()) fail(f.path(key), "must be one of " + list);
  const std::string given = f.at(key).get<std::string>();
  for (Enum v : values)
    if (name_of(v) == given) return v;
  fail(f.path(key), "must be one of " + list + " (not \"" + swarm::printable(given) + "\")");
}

std::size_t particle_count(const swarm::Preset& p) {
  if (const auto* list = std::get_if<std::vector<swarm::Particle>>(&p.particles))
    return list->size();
  return std::size_t(std::get<swarm::SwarmSpec>(p.particles).count);
}

LessonTask task_of(const json& j, const std::string& path, const swarm::Preset& scene) {
  if (!j.is_object()) fail(path, "must be a JSON object");
  if (!j.contains("kind")) fail(path + ".kind", "missing (\"measure\", \"choice\" or \"predict\")");
  LessonTask t;
  {
    const Fields kind(j, path, {"kind", "prompt", "quantity", "particle", "tolerance", "window",
                                "options", "answer", "feedback", "outcome"});
    t.kind = named(kind, "kind",
                   {LessonTask::Kind::measure, LessonTask::Kind::choice, LessonTask::Kind::predict});
  }
  const std::size_t N = particle_count(scene);
  if (t.kind == LessonTask::Kind::measure) {
    const Fields f(j, path, {"kind", "prompt", "quantity", "particle", "tolerance", "window"});
    t.prompt = f.text("prompt", kMaxTextBytes, "the question to show");
    check_prose(t.prompt, f.path("prompt"));
    if (!f.has("quantity"))
      fail(f.path("quantity"), "missing (period, omega, M, E, P or T)");
    t.quantity = named(f, "quantity",
                       {Quantity::period, Quantity::omega, Quantity::M, Quantity::E, Quantity::P,
                        Quantity::T});
    if (t.quantity == Quantity::period)
      require(scene.J > 0, f.path("quantity"),
              "a period needs J > 0 in this step's preset (it has J = " + format(scene.J) + ")");
    if (t.quantity == Quantity::P || t.quantity == Quantity::T)
      require(bool(scene.container_radius), f.path("quantity"),
              "P and T are measured at the wall: this step's preset needs a container");
    if (f.has("particle"))
      t.particle = f.index("particle", N,
                           "must be below the preset's " + std::to_string(N) + " particles");
    if (f.has("tolerance")) {
      t.tolerance = f.number("tolerance");
      require(t.tolerance > 0, f.path("tolerance"), "must be > 0");
      require(t.tolerance < 1, f.path("tolerance"), "must be < 1 (it is relative: 0.02 is 2%)");
    }
    if (f.has("window")) {
      t.window = f.number("window");
      require(t.window >= 0, f.path("window"), "must be >= 0");
      require(t.quantity == Quantity::P || t.quantity == Quantity::T, f.path("window"),
              "only P and T are averaged over a window");
    }
  } else if (t.kind == LessonTask::Kind::choice) {
    const Fields f(j, path, {"kind", "prompt", "options", "answer", "feedback"});
    t.prompt = f.text("prompt", kMaxTextBytes, "the question to show");
    check_prose(t.prompt, f.path("prompt"));
    t.options = option_list(f, "options");
    if (!f.has("answer")) fail(f.path("answer"), "missing (the index of the right option)");
    t.answer = f.index("answer", t.options.size(),
                       "must be an index into options (0 to " +
                           std::to_string(t.options.size() - 1) + ")");
    if (f.has("feedback")) {
      t.feedback = option_list(f, "feedback");
      require(t.feedback.size() == t.options.size(), f.path("feedback"),
              "must give one text per option (" + std::to_string(t.options.size()) + ")");
    }
  } else {
    const Fields f(j, path, {"kind", "prompt", "options", "outcome"});
    t.prompt = f.text("prompt", kMaxTextBytes, "the question to show");
    check_prose(t.prompt, f.path("prompt"));
    t.options = option_list(f, "options");
    if (f.has("outcome")) {
      t.outcome = f.text("outcome", kMaxTextBytes, "what the run shows");
      check_prose(t.outcome, f.path("outcome"));
    }
  }
  return t;
}

LessonStep step_of(const json& j, const std::string& path, const PresetLookup& lookup,
                   const std::optional<swarm::Preset>& running) {
  const Fields f(j, path, {"text", "preset", "show", "hide", "run", "task", "claims"});
  LessonStep s;
  s.text = f.text("text", kMaxTextBytes, "what the step says");
  check_prose(s.text, f.path("text"));
  if (f.has("preset")) {
    const json& p = f.at("preset");
    swarm::PresetParse parsed;
    if (p.is_string()) {
      s.preset_name = p.get<std::string>();
      parsed = lookup(s.preset_name);
      if (!parsed.preset) fail(f.path("preset"), parsed.error);
    } else if (p.is_object()) {
      parsed = swarm::parse_preset(p.dump());
      if (!parsed.preset) throw Invalid{f.path("preset") + "." + parsed.error};
    } else {
      fail(f.path("preset"), "must be a shipped preset's file name or a preset object");
    }
    s.preset = std::move(parsed.preset);
  } else if (!running) {
    fail(f.path("preset"), "missing (the first step sets the scene with a preset)");
  }
  const swarm::Preset& scene = s.preset ? *s.preset : *running;
  if (f.has("show")) {
    const Fields show(f.at("show"), f.path("show"), {"plot", "select", "overlay"});
    if (show.has("plot"))
      s.plot = named(show, "plot",
                     {LessonPlot::wall, LessonPlot::energy, LessonPlot::expansion,
                      LessonPlot::compare, LessonPlot::particle, LessonPlot::projects});
    if (show.has("select")) {
      const std::size_t N = particle_count(scene);
      s.select = show.index("select", N,
                            "must be below the preset's " + std::to_string(N) + " particles");
    }
    if (show.has("overlay"))
      s.overlay = named(show, "overlay",
                        {LessonOverlay::none, LessonOverlay::springs, LessonOverlay::springs_to_cm});
  }
  if (f.has("hide")) {
    const json& list = f.at("hide");
    const char* rule = "must be a list of what to hide: \"readouts\", \"card\", \"plots\"";
    require(list.is_array() && !list.empty(), f.path("hide"), rule);
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string item = f.path("hide") + "[" + std::to_string(i) + "]";
      require(list[i].is_string(), item, rule);
      const std::string name = list[i].get<std::string>();
      bool known = false;
      for (LessonHidden h : {LessonHidden::readouts, LessonHidden::card, LessonHidden::plots})
        if (name_of(h) == name) {
          require(!s.hides(h), item, "\"" + name + "\" is listed twice");
          s.hide.push_back(h);
          known = true;
        }
      require(known, item,
              std::string(rule) + " (not \"" + swarm::printable(name) + "\")");
    }
  }
  if (f.has("run")) {
    const Fields run(f.at("run"), f.path("run"), {"until", "loop"});
    require(run.has("until") != run.has("loop"), f.path("run"),
            "give either \"until\": a time or \"loop\": true, not both and not neither");
    if (run.has("until")) {
      const double until = run.number("until");
      require(until > 0 && until <= kMaxRunUntil, run.path("until"),
              "must be > 0 and at most " + format(kMaxRunUntil) + " (the time the run lasts to)");
      s.run_until = until;
    } else {
      require(run.at("loop") == true, run.path("loop"),
              "must be true (the run starts again whenever it ends)");
      s.run_loop = true;
    }
  }
  if (f.has("task")) s.task = task_of(f.at("task"), f.path("task"), scene);
  if (f.has("claims")) {
    const bool choice = s.task && s.task->kind == LessonTask::Kind::choice;
    ClaimsParse claims = parse_claims(f.at("claims").dump(), f.path("claims"), scene,
                                      choice ? s.task->options.size() : 0, lookup);
    if (!claims.error.empty()) throw Invalid{claims.error};
    s.claims = std::move(claims.claims);
  }
  return s;
}

/// A text of the lesson a student reads, where it stands ("steps[2].task.options[1]") and how
/// long it may be there.
struct LessonText {
  std::string path;
  const std::string* text;
  std::size_t max_bytes;
};

std::vector<LessonText> lesson_texts(const Lesson& l) {
  std::vector<LessonText> out = {{"title", &l.title, kMaxTitleBytes},
                                 {"summary", &l.summary, kMaxTextBytes}};
  for (std::size_t i = 0; i < l.steps.size(); ++i) {
    const LessonStep& s = l.steps[i];
    const std::string step = "steps[" + std::to_string(i) + "]";
    out.push_back({step + ".text", &s.text, kMaxTextBytes});
    if (!s.task) continue;
    const std::string task = step + ".task";
    out.push_back({task + ".prompt", &s.task->prompt, kMaxTextBytes});
    for (std::size_t k = 0; k < s.task->options.size(); ++k)
      out.push_back({task + ".options[" + std::to_string(k) + "]", &s.task->options[k], kMaxTextBytes});
    for (std::size_t k = 0; k < s.task->feedback.size(); ++k)
      out.push_back({task + ".feedback[" + std::to_string(k) + "]", &s.task->feedback[k], kMaxTextBytes});
    if (!s.task->outcome.empty()) out.push_back({task + ".outcome", &s.task->outcome, kMaxTextBytes});
  }
  return out;
}

/// The lesson's own translations: for each language the app speaks (not English), texts of this
/// lesson to what to show instead, each held to the rules of the field it translates (a title
/// to a title's length) and keeping its text's device choices and emphasis.
void read_translations(const Fields& f, Lesson& l) {
  const json& all = f.at("translations");
  require(all.is_object(), "translations",
          "must be an object of language codes (" + language_codes("", true) + ") to tables");
  const std::vector<LessonText> texts = lesson_texts(l);
  for (const auto& [code, table] : all.items()) {
    const std::string path = "translations." + swarm::printable(code);
    require(find_language(code) && code != source_language().code && code != pseudo_language().code, path,
            "not a language the app speaks (" + language_codes("", true) + ")");
    require(table.is_object(), path, "must be an object of this lesson's English texts to their translations");
    for (const auto& [english, shown] : table.items()) {
      const std::string key = path + ".\"" + swarm::printable(english.substr(0, 40)) + "\"";
      // The first field holding this text names it; a text in several fields takes the
      // strictest limit.
      const LessonText* field = nullptr;
      std::size_t max_bytes = kMaxTextBytes;
      for (const LessonText& t : texts)
        if (*t.text == english) {
          if (!field) field = &t;
          max_bytes = std::min(max_bytes, t.max_bytes);
        }
      require(field, key, "not a text of this lesson (the key is the English text, exactly)");
      const std::string at = key + " (" + field->path + ")";
      require(shown.is_string() && !shown.get<std::string>().empty(), at,
              "must be a non-empty string");
      const std::string text = shown.get<std::string>();
      require(text.size() <= max_bytes, at,
              "must be at most " + std::to_string(max_bytes) +
                  " bytes long, as the English is (it has " + std::to_string(text.size()) + ")");
      check_prose(text, at);
      require(device_choices(text) == device_choices(english), at,
              "must keep the English text's {tap|click} choices, with as many alternatives each");
      l.translations[code][english] = text;
    }
  }
}

Lesson lesson_of(const json& j, const PresetLookup& lookup) {
  const Fields f(j, "", {"lesson", "id", "title", "summary", "steps", "translations"});
  if (!f.has("lesson"))
    fail("lesson", "missing the key \"lesson\": 1 (the lesson format's version)");
  require(f.at("lesson") == kLessonVersion, "lesson",
          "must be " + std::to_string(kLessonVersion) + " (the only lesson version so far)");
  Lesson l;
  l.id = f.text("id", kMaxIdBytes, "a short name such as \"one-period\"");
  for (char c : l.id)
    require((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-', "id",
            "may hold only lowercase letters, digits and '-'");
  l.title = f.text("title", kMaxTitleBytes, "the lesson's title");
  check_prose(l.title, "title");
  l.summary = f.text("summary", kMaxTextBytes, "one or two sentences on what it teaches");
  check_prose(l.summary, "summary");
  if (!f.has("steps")) fail("steps", "missing (a list of 1 to 100 steps)");
  const json& steps = f.at("steps");
  require(steps.is_array() && !steps.empty() && steps.size() <= kMaxSteps, "steps",
          "must be a list of 1 to " + std::to_string(kMaxSteps) + " steps");
  std::optional<swarm::Preset> running;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    l.steps.push_back(step_of(steps[i], "steps[" + std::to_string(i) + "]", lookup, running));
    if (l.steps.back().preset) running = l.steps.back().preset;
  }
  if (f.has("translations")) read_translations(f, l);
  return l;
}


}  // namespace

LessonParse parse_lesson(std::string_view json_text, const PresetLookup& lookup) {
  LessonParse out;
  if (json_text.size() > kMaxLessonBytes) {
    out.error = "lesson: " + std::to_string(json_text.size()) + " bytes; a lesson may be at most " +
                std::to_string(kMaxLessonBytes) + " bytes";
    return out;
  }
  if (const std::size_t nul = json_text.find('\0'); nul != std::string_view::npos) {
    out.error = "lesson: a NUL byte at offset " + std::to_string(nul) + " (a lesson is JSON text)";
    return out;
  }
  try {
    const json j = swarm::parse_strict_json(json_text);
    out.lesson = lesson_of(j, lookup);
  } catch (const swarm::DuplicateKey& e) {
    out.error = e.what();
  } catch (const Invalid& e) {
    out.error = e.message;
  } catch (const json::parse_error& e) {
    out.error = "lesson: not valid JSON at " + swarm::json_syntax_error(e, json_text) +
                " (a lesson is one JSON object, see docs/lessons.md)";
  } catch (const json::exception&) {
    out.error = "lesson: not a lesson the app can read (a value of the wrong type)";
  }
  return out;
}

bool looks_like_lesson(std::string_view json_text) {
  // Text that is not JSON, or too large for a lesson, is a lesson when its first key is
  // "lesson", so that its message is a lesson's.
  const std::size_t brace = json_text.find_first_not_of(" \t\r\n");
  if (brace != std::string_view::npos && json_text[brace] == '{') {
    const std::size_t key = json_text.find_first_not_of(" \t\r\n", brace + 1);
    if (key != std::string_view::npos && json_text.substr(key, 8) == "\"lesson\"") return true;
  }
  if (json_text.size() > kMaxLessonBytes) return false;
  const json j = json::parse(json_text.begin(), json_text.end(), nullptr, false);
  return j.is_object() && j.contains("lesson");
}

std::string_view name_of(LessonPlot plot) {
  switch (plot) {
    case LessonPlot::wall: return "wall";
    case LessonPlot::energy: return "energy";
    case LessonPlot::expansion: return "expansion";
    case LessonPlot::compare: return "compare";
    case LessonPlot::particle: return "particle";
    case LessonPlot::projects: return "projects";
  }
  return "";
}

std::string_view name_of(LessonOverlay overlay) {
  switch (overlay) {
    case LessonOverlay::none: return "none";
    case LessonOverlay::springs: return "springs";
    case LessonOverlay::springs_to_cm: return "springs-to-cm";
  }
  return "";
}

std::string_view name_of(Quantity quantity) {
  switch (quantity) {
    case Quantity::period: return "period";
    case Quantity::omega: return "omega";
    case Quantity::M: return "M";
    case Quantity::E: return "E";
    case Quantity::P: return "P";
    case Quantity::T: return "T";
  }
  return "";
}

std::string_view name_of(LessonHidden hidden) {
  switch (hidden) {
    case LessonHidden::readouts: return "readouts";
    case LessonHidden::card: return "card";
    case LessonHidden::plots: return "plots";
  }
  return "";
}

std::vector<std::string> Lesson::texts() const {
  std::vector<std::string> out;
  for (const LessonText& t : lesson_texts(*this)) out.push_back(*t.text);
  return out;
}

const std::string* Lesson::translation(const std::string& code, const std::string& english) const {
  const auto language = translations.find(code);
  if (language == translations.end()) return nullptr;
  const auto it = language->second.find(english);
  return it == language->second.end() ? nullptr : &it->second;
}

bool LessonStep::hides(LessonHidden what) const {
  return std::find(hide.begin(), hide.end(), what) != hide.end();
}

std::string quantity_symbol(Quantity quantity, bool repulsive) {
  if (quantity == Quantity::omega) return repulsive ? "\u03a9" : "\u03c9";
  if (quantity == Quantity::period) return "the period";
  return std::string(name_of(quantity));
}

std::string_view name_of(LessonTask::Kind kind) {
  switch (kind) {
    case LessonTask::Kind::measure: return "measure";
    case LessonTask::Kind::choice: return "choice";
    case LessonTask::Kind::predict: return "predict";
  }
  return "";
}

Marking mark_measurement(const LessonTask& task, double answer, double expected,
                         const std::string& symbol) {
  // Whole sentences through the translator, in the language the student reads (app/i18n).
  Marking m;
  if (!std::isfinite(answer)) {
    m.feedback = translator().numbers(tr("Type a number, e.g. 4.44."));
    return m;
  }
  if (!std::isfinite(expected)) {
    m.feedback = sentence(
        tr("The running simulation has no %s to compare with right now (has the scene changed?)."),
        symbol.c_str());
    return m;
  }
  const double off = std::abs(answer - expected) / std::max(std::abs(expected), 1e-300);
  m.correct = off <= task.tolerance;
  const std::string percent = format(100 * task.tolerance);
  if (*m.correct)
    m.feedback = sentence(tr("Right: the simulation has %s = %s, and you are within %s%% of it."),
                          symbol.c_str(), format(expected).c_str(), percent.c_str());
  else if (answer != 0 && (answer < 0) != (expected < 0))
    // "200 % too large" for -E would hide the one thing that is wrong.
    m.feedback = sentence(expected < 0 ? tr("Not yet: the sign is wrong (%s is negative here). Look again.")
                                       : tr("Not yet: the sign is wrong (%s is positive here). Look again."),
                          symbol.c_str());
  else
    m.feedback = sentence(
        answer > expected
            ? tr("Not yet: your value is %s%% too large (within %s%% counts). Measure again.")
            : tr("Not yet: your value is %s%% too small (within %s%% counts). Measure again."),
        format(100 * off).c_str(), percent.c_str());
  return m;
}

std::string without_emphasis(std::string_view text) {
  std::string plain;
  for (const char c : text)
    if (c != '*') plain += c;
  return plain;
}

Marking mark_option(const LessonTask& task, std::size_t option) {
  Marking m;
  if (option >= task.options.size()) {
    m.feedback = sentence(tr("Pick one of the %zu options."), task.options.size());
    return m;
  }
  if (task.kind == LessonTask::Kind::predict) {
    const std::string picked = tr(task.options[option].c_str());
    m.feedback = task.outcome.empty()
                     ? sentence(tr("Your prediction: \u201c%s\u201d."), picked.c_str())
                     : sentence(tr("Your prediction: \u201c%s\u201d. Now run it and compare: %s"),
                                picked.c_str(), tr(task.outcome.c_str()));
    return m;
  }
  m.correct = task.answer && option == *task.answer;
  if (option < task.feedback.size())
    m.feedback = task.feedback[option];
  else
    m.feedback = *m.correct ? tr("Right.") : tr("Not this one: look again and try another.");
  return m;
}

}  // namespace swarmlab
