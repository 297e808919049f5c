#include "lessons/lesson.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>

#include "lessons/lesson_file.h"

using namespace swarmlab;

namespace {

using ojson = nlohmann::ordered_json;

/// An isolated pair (J = 1, M = 2: period 2 pi / sqrt 2) and a gas in a sphere, by name.
const char* kPair = R"({"J": 1.0, "particles": [{"m": 1, "r": [0.5, 0, 0], "v": [0, 0.7, 0]},
  {"m": 1, "r": [-0.5, 0, 0], "v": [0, -0.7, 0]}], "dt": 0.01, "duration": 5})";
const char* kGas = R"({"J": 0.0, "particles": {"count": 50, "position_radius": 1,
  "velocity": {"speed": 1}}, "container": {"radius": 1}, "dt": 0.01, "duration": 5})";

swarm::PresetParse test_lookup(const std::string& name) {
  if (name == "pair.json") return swarm::parse_preset(kPair);
  if (name == "gas.json") return swarm::parse_preset(kGas);
  return {std::nullopt, "no shipped preset \"" + name + "\""};
}

ojson base_lesson() {
  return ojson::parse(R"({"lesson": 1, "id": "t", "title": "T", "summary": "S",
    "steps": [
      {"text": "Watch *this*.", "preset": "pair.json",
       "show": {"plot": "energy", "select": 1, "overlay": "springs-to-cm"},
       "task": {"kind": "measure", "prompt": "Period?", "quantity": "period", "tolerance": 0.02}},
      {"text": "Pick.", "task": {"kind": "choice", "prompt": "Which?", "options": ["a", "b"],
       "answer": 1, "feedback": ["no", "yes"]}},
      {"text": "Guess.", "preset": "gas.json",
       "task": {"kind": "predict", "prompt": "What?", "options": ["up", "down"], "outcome": "it goes up"}},
      {"text": "Read T.", "task": {"kind": "measure", "prompt": "T?", "quantity": "T", "window": 1}}]})");
}

std::string error_of(const std::string& text) {
  const LessonParse parsed = parse_lesson(text, test_lookup);
  return parsed.lesson ? std::string() : parsed.error;
}

std::string error_of_json(const ojson& lesson) { return error_of(lesson.dump()); }

}  // namespace

TEST_CASE("a valid lesson reads into its steps, scenes and tasks") {
  const LessonParse parsed = parse_lesson(base_lesson().dump(), test_lookup);
  REQUIRE_MESSAGE(parsed.lesson, parsed.error);
  const Lesson& l = *parsed.lesson;
  CHECK(l.id == "t");
  REQUIRE(l.steps.size() == 4);
  CHECK(l.steps[0].preset_name == "pair.json");
  REQUIRE(l.steps[0].preset);
  CHECK(l.steps[0].preset->J == 1.0);
  CHECK(l.steps[0].plot == LessonPlot::energy);
  CHECK(l.steps[0].select == std::size_t(1));
  CHECK(l.steps[0].overlay == LessonOverlay::springs_to_cm);
  CHECK(l.steps[0].task->quantity == Quantity::period);
  CHECK(!l.steps[1].preset);
  CHECK(l.steps[1].task->answer == std::size_t(1));
  CHECK(l.steps[2].task->kind == LessonTask::Kind::predict);
  CHECK(l.steps[3].task->window == 1.0);
  CHECK(l.steps[3].task->tolerance == 0.02);  // the default
}

TEST_CASE("a step can open every plot tab by name, the Projects tab too (lesson 7 needs it)") {
  for (const auto& [name, plot] : {std::pair{"particle", LessonPlot::particle},
                                   std::pair{"projects", LessonPlot::projects}}) {
    ojson lesson = base_lesson();
    lesson["steps"][0]["show"]["plot"] = name;
    const LessonParse parsed = parse_lesson(lesson.dump(), test_lookup);
    REQUIRE_MESSAGE(parsed.lesson, parsed.error);
    CHECK(parsed.lesson->steps[0].plot == plot);
    CHECK(name_of(plot) == name);
  }
}

TEST_CASE("every rule of the lesson format is refused with the field and the rule") {
  struct Case {
    const char* pointer;  // JSON pointer to set, or remove when value is empty
    const char* value;
    const char* message;
  };
  const Case cases[] = {
      {"/lesson", "2", "lesson: must be 1 (the only lesson version so far)"},
      {"/lesson", "", "lesson: missing the key \"lesson\": 1 (the lesson format's version)"},
      {"/id", "", "id: missing (a short name such as \"one-period\")"},
      {"/id", "\"One Period\"", "id: may hold only lowercase letters, digits and '-'"},
      {"/title", "\"\"", "title: must not be empty"},
      {"/title", "3", "title: must be a string"},
      {"/summary", "", "summary: missing (one or two sentences on what it teaches)"},
      {"/extra", "1", "extra: unknown key (allowed here: lesson, id, title, summary, steps, translations)"},
      {"/steps", "[]", "steps: must be a list of 1 to 100 steps"},
      {"/steps/0/text", "", "steps[0].text: missing (what the step says)"},
      {"/steps/0/text", "\"an *open emphasis\"",
       "steps[0].text: an emphasis is not closed in its paragraph (write *like this*)"},
      {"/steps/0/text", "\"a\\u0007bell\"",
       "steps[0].text: control character U+0007 (only line breaks are allowed)"},
      {"/steps/0/text", "\"a\\u007fdel\"",
       "steps[0].text: control character U+007F (only line breaks are allowed)"},
      {"/steps/0/text", "\"a\\u0085next line\"",
       "steps[0].text: control character U+0085 (only line breaks are allowed)"},
      {"/steps/0/text", "\"a\\u009b31m CSI\"",
       "steps[0].text: control character U+009B (only line breaks are allowed)"},
      {"/title", "\"\\u202e\"",
       "title: must show something (it holds only spaces or invisible characters such as U+202E)"},
      {"/summary", "\" \\u200b\\u200e\\u2066\\ufeff \"",
       "summary: must show something (it holds only spaces or invisible characters such as U+200B)"},
      {"/steps/0/text", "\"  \\n\\u3000 \"", "steps[0].text: must show something (it holds only spaces)"},
      {"/steps/0/preset", "", "steps[0].preset: missing (the first step sets the scene with a preset)"},
      {"/steps/0/preset", "\"nope.json\"", "steps[0].preset: no shipped preset \"nope.json\""},
      {"/steps/0/preset", "3", "steps[0].preset: must be a shipped preset's file name or a preset object"},
      {"/steps/0/preset", "{\"J\": 1, \"particles\": [{\"m\": -1, \"r\": [0,0,0], \"v\": [0,0,0]}]}",
       "steps[0].preset.particles[0].m: must be > 0"},
      {"/steps/0/show/plot", "\"pv\"",
       "steps[0].show.plot: must be one of \"wall\", \"energy\", \"expansion\", \"compare\", "
       "\"particle\", \"projects\" (not \"pv\")"},
      {"/steps/0/show/select", "2", "steps[0].show.select: must be below the preset's 2 particles"},
      {"/steps/0/show/select", "-1", "steps[0].show.select: must be a whole number >= 0"},
      {"/steps/0/show/overlay", "\"springs-cm\"",
       "steps[0].show.overlay: must be one of \"none\", \"springs\", \"springs-to-cm\" (not "
       "\"springs-cm\")"},
      {"/steps/0/show/zoom", "1", "steps[0].show.zoom: unknown key (allowed here: plot, select, overlay)"},
      {"/steps/0/task/kind", "", "steps[0].task.kind: missing (\"measure\", \"choice\" or \"predict\")"},
      {"/steps/0/task/kind", "\"essay\"",
       "steps[0].task.kind: must be one of \"measure\", \"choice\", \"predict\" (not \"essay\")"},
      {"/steps/0/task/prompt", "", "steps[0].task.prompt: missing (the question to show)"},
      {"/steps/0/task/quantity", "\"mass\"",
       "steps[0].task.quantity: must be one of \"period\", \"omega\", \"M\", \"E\", \"P\", \"T\" "
       "(not \"mass\")"},
      {"/steps/0/task/quantity", "\"P\"",
       "steps[0].task.quantity: P and T are measured at the wall: this step's preset needs a "
       "container"},
      {"/steps/0/task/tolerance", "0", "steps[0].task.tolerance: must be > 0"},
      {"/steps/0/task/tolerance", "1.5", "steps[0].task.tolerance: must be < 1 (it is relative: 0.02 is 2%)"},
      {"/steps/0/task/tolerance", "\"2%\"", "steps[0].task.tolerance: must be a number"},
      {"/steps/0/task/particle", "5", "steps[0].task.particle: must be below the preset's 2 particles"},
      {"/steps/0/task/window", "1", "steps[0].task.window: only P and T are averaged over a window"},
      {"/steps/0/task/options", "[\"a\"]",
       "steps[0].task.options: unknown key (allowed here: kind, prompt, quantity, particle, "
       "tolerance, window)"},
      {"/steps/3/task/window", "-1", "steps[3].task.window: must be >= 0"},
      {"/steps/1/task/options", "[\"only one\"]", "steps[1].task.options: must be a list of 2 to 8 strings"},
      {"/steps/1/task/options", "[\"a\", \"\"]", "steps[1].task.options[1]: must be a non-empty string"},
      {"/steps/1/task/answer", "", "steps[1].task.answer: missing (the index of the right option)"},
      {"/steps/1/task/answer", "2", "steps[1].task.answer: must be an index into options (0 to 1)"},
      {"/steps/1/task/feedback", "[\"a\", \"b\", \"c\"]",
       "steps[1].task.feedback: must give one text per option (2)"},
      {"/steps/2/task/answer", "0",
       "steps[2].task.answer: unknown key (allowed here: kind, prompt, options, outcome)"},
      {"/steps/2/task/options", "", "steps[2].task.options: missing (a list of 2 to 8 strings is required)"},
      {"/steps/2/task/outcome", "\"\"", "steps[2].task.outcome: must not be empty"},
  };
  for (const Case& c : cases) {
    ojson lesson = base_lesson();
    const ojson::json_pointer at(c.pointer);
    if (*c.value)
      lesson[at] = ojson::parse(c.value);
    else
      lesson.at(at.parent_pointer()).erase(at.back());
    CAPTURE(c.pointer);
    CHECK(error_of_json(lesson) == c.message);
  }
}

TEST_CASE("a period needs an attractive scene") {
  ojson lesson = base_lesson();
  lesson["steps"][0]["preset"] = ojson::parse(kPair);
  lesson["steps"][0]["preset"]["J"] = -1.0;
  CHECK(error_of_json(lesson) ==
        "steps[0].task.quantity: a period needs J > 0 in this step's preset (it has J = -1)");
}

TEST_CASE("a step without a preset is checked against the scene before it") {
  ojson lesson = base_lesson();
  lesson["steps"][1]["show"] = {{"select", 40}};  // step 1 still shows the pair
  CHECK(error_of_json(lesson) == "steps[1].show.select: must be below the preset's 2 particles");
  lesson["steps"][3]["show"] = {{"select", 40}};  // step 3 shows the gas of 50
  lesson["steps"][1].erase("show");
  CHECK(error_of_json(lesson).empty());
}

TEST_CASE("lesson text that is not one JSON object of bounded size is refused") {
  CHECK(error_of(R"({"lesson": 1, "id": "a", "id": "b"})") == "id: given twice (each key at most once)");
  CHECK(error_of(R"({"lesson": 1, "steps": [{"text": "a", "text": "b"}]})") ==
        "steps[0].text: given twice (each key at most once)");
  CHECK(error_of(base_lesson().dump() + " {}").rfind("lesson: not valid JSON", 0) == 0);
  CHECK(error_of("[1, 2]") == "lesson: must be a JSON object");
  CHECK(error_of(std::string("{\"lesson\": 1}\0", 14)).rfind("lesson: a NUL byte at offset 13", 0) == 0);
  std::string huge = base_lesson().dump();
  huge.insert(huge.size() - 1, ", \"pad\": \"" + std::string(kMaxLessonBytes, 'x') + "\"");
  CHECK(error_of(huge).rfind("lesson: " + std::to_string(huge.size()) + " bytes; a lesson may be at most", 0) == 0);
}

TEST_CASE("a lesson is told from a preset by its \"lesson\" key") {
  CHECK(looks_like_lesson(base_lesson().dump()));
  CHECK_FALSE(looks_like_lesson(kPair));
  CHECK_FALSE(looks_like_lesson("not json"));
  CHECK(looks_like_lesson(R"({"lesson": 7})"));  // then refused as a lesson, by its version
  CHECK(looks_like_lesson(R"( {"lesson": 1, "id": "cut short)"));  // broken, but a lesson's
  CHECK_FALSE(looks_like_lesson(R"({"J": 1, "lesson)"));
}

TEST_CASE("a measurement is right within the relative tolerance of the simulation's value") {
  LessonTask task;
  task.kind = LessonTask::Kind::measure;
  task.quantity = Quantity::period;
  task.tolerance = 0.02;
  const double period = 2 * M_PI / std::sqrt(2.0);  // the pair: 2 pi / sqrt(J M)
  CHECK(*mark_measurement(task, 4.44, period, "E").correct);
  CHECK(*mark_measurement(task, period * 1.019, period, "E").correct);
  CHECK_FALSE(*mark_measurement(task, period * 1.021, period, "E").correct);
  CHECK_FALSE(*mark_measurement(task, period * 0.979, period, "E").correct);
  CHECK_FALSE(*mark_measurement(task, period / 2, period, "E").correct);  // timing KE's 2 omega
  CHECK(mark_measurement(task, period * 1.5, period, "the period").feedback.find("50% too large") !=
        std::string::npos);
  CHECK_FALSE(mark_measurement(task, NAN, period, "E").correct);
  CHECK_FALSE(mark_measurement(task, 4.44, NAN, "E").correct);  // nothing to compare with
  task.tolerance = 0.1;
  CHECK(*mark_measurement(task, -1.05, -1.0, "E").correct);  // negative energies compare by size
  CHECK_FALSE(*mark_measurement(task, 1.0, -1.0, "E").correct);
}

TEST_CASE("feedback: a sign error says the sign is wrong; the quantity is named as asked") {
  LessonTask task;
  task.kind = LessonTask::Kind::measure;
  task.quantity = Quantity::E;
  // Not "200% too large": the size is right, only the sign is not.
  const Marking sign = mark_measurement(task, 1.0, -1.0, "E");
  CHECK_FALSE(*sign.correct);
  CHECK(sign.feedback == "Not yet: the sign is wrong (E is negative here). Look again.");
  CHECK(sign.feedback.find('%') == std::string::npos);
  // A repulsive system's omega is its growth rate Omega, as lesson 3 asks for it.
  task.quantity = Quantity::omega;
  CHECK(quantity_symbol(Quantity::omega, true) == "\u03a9");
  CHECK(quantity_symbol(Quantity::omega, false) == "\u03c9");
  const Marking right = mark_measurement(task, 1.8, 1.8028, quantity_symbol(Quantity::omega, true));
  CHECK(right.feedback.rfind("Right: the simulation has \u03a9 = 1.803", 0) == 0);
  CHECK(right.feedback.find("omega") == std::string::npos);
}

TEST_CASE("a step's hide and run fields: what they hold and each rule by name") {
  ojson lesson = base_lesson();
  lesson["steps"][1]["hide"] = {"readouts", "card"};
  lesson["steps"][2]["run"] = {{"until", 40}};
  lesson["steps"][3]["run"] = {{"loop", true}};
  const LessonParse ok = parse_lesson(lesson.dump(), test_lookup);
  REQUIRE_MESSAGE(ok.lesson, ok.error);
  const Lesson& l = *ok.lesson;
  CHECK(l.steps[1].hides(LessonHidden::readouts));
  CHECK(l.steps[1].hides(LessonHidden::card));
  CHECK_FALSE(l.steps[1].hides(LessonHidden::plots));
  CHECK(l.steps[0].hide.empty());
  CHECK(*l.steps[2].run_until == 40);
  CHECK_FALSE(l.steps[2].run_loop);
  CHECK(l.steps[3].run_loop);
  CHECK_FALSE(l.steps[3].run_until);

  auto refused = [&](const char* field, ojson value) {
    ojson broken = base_lesson();
    broken["steps"][1][field] = std::move(value);
    return error_of_json(broken);
  };
  CHECK(refused("hide", "readouts") ==
        "steps[1].hide: must be a list of what to hide: \"readouts\", \"card\", \"plots\"");
  CHECK(refused("hide", ojson::array()) ==
        "steps[1].hide: must be a list of what to hide: \"readouts\", \"card\", \"plots\"");
  CHECK(refused("hide", {"readouts", "answer"}) ==
        "steps[1].hide[1]: must be a list of what to hide: \"readouts\", \"card\", \"plots\" "
        "(not \"answer\")");
  CHECK(refused("hide", {"card", "card"}) == "steps[1].hide[1]: \"card\" is listed twice");
  CHECK(refused("run", {{"until", 0}}) ==
        "steps[1].run.until: must be > 0 and at most 1e+06 (the time the run lasts to)");
  CHECK(refused("run", {{"until", "long"}}) == "steps[1].run.until: must be a number");
  CHECK(refused("run", {{"loop", false}}) ==
        "steps[1].run.loop: must be true (the run starts again whenever it ends)");
  CHECK(refused("run", {{"loop", true}, {"until", 3}}) ==
        "steps[1].run: give either \"until\": a time or \"loop\": true, not both and not neither");
  CHECK(refused("run", ojson::object()) ==
        "steps[1].run: give either \"until\": a time or \"loop\": true, not both and not neither");
  CHECK(refused("run", {{"repeat", true}}).rfind("steps[1].run.repeat: unknown key (allowed here: until, loop)", 0) == 0);
}

TEST_CASE("device words in lesson text are checked where they are written") {
  ojson lesson = base_lesson();
  lesson["steps"][0]["text"] = "{Tap|Click} a ball, then {tap *Play*|click *Play*|press *Space*}.";
  CHECK(error_of_json(lesson).empty());
  lesson["steps"][0]["text"] = "{tap} a ball";
  CHECK(error_of_json(lesson) ==
        "steps[0].text: a device choice is {touch words|mouse words} or {touch|mouse|keyboard "
        "words}: 2 or 3 non-empty alternatives split by '|', closed on the same line");
  lesson["steps"][0]["text"] = "a } alone";
  CHECK(error_of_json(lesson).rfind("steps[0].text: a '}' with no '{' before it", 0) == 0);
  lesson = base_lesson();
  lesson["steps"][1]["task"]["prompt"] = "{tap|click|press Enter|shout}";
  CHECK(error_of_json(lesson).rfind("steps[1].task.prompt: a device choice is", 0) == 0);
}

TEST_CASE("text that is not JSON is refused in one sentence, without the parser's own codes") {
  const std::string e = error_of("not json");
  CHECK(e.rfind("lesson: not valid JSON at line 1, column 2: invalid literal; last read: 'no'", 0) == 0);
  // Where it breaks, as an editor counts lines and columns (a character, not a byte).
  CHECK(error_of("{\"lesson\": 1,\n \"title\": \"\u00e9t\u00e9\" x}") ==
        "lesson: not valid JSON at line 2, column 17: invalid literal; last read: '\"\u00e9t\u00e9\" x'; expected '}' "
        "(a lesson is one JSON object, see docs/lessons.md)");
  CHECK(e.find("json.exception") == std::string::npos);
}

TEST_CASE("a choice is marked with its option's feedback; a prediction is recorded, not marked") {
  LessonTask choice;
  choice.kind = LessonTask::Kind::choice;
  choice.options = {"a", "b"};
  choice.answer = 1;
  choice.feedback = {"no", "yes"};
  CHECK(*mark_option(choice, 1).correct);
  CHECK(mark_option(choice, 1).feedback == "yes");
  CHECK_FALSE(*mark_option(choice, 0).correct);
  CHECK(mark_option(choice, 0).feedback == "no");
  CHECK_FALSE(mark_option(choice, 5).correct);
  LessonTask predict;
  predict.kind = LessonTask::Kind::predict;
  predict.options = {"up", "down"};
  predict.outcome = "it goes up";
  const Marking m = mark_option(predict, 1);
  CHECK_FALSE(m.correct);
  CHECK(m.feedback.find("down") != std::string::npos);
  CHECK(m.feedback.find("it goes up") != std::string::npos);
}

TEST_CASE("every shipped lesson validates") {
  // Shipped presets come from assets/presets. Lessons may name presets that another part of
  // the project ships (the Appendix B projects); until they exist a stand-in of the same kind
  // (a gas in a sphere, J > 0) takes their place, and the test says which.
  const PresetLookup shipped = shipped_preset_lookup(SWARM_PRESET_DIR);
  std::set<std::string> stand_ins;
  const PresetLookup lookup = [&](const std::string& name) {
    swarm::PresetParse p = shipped(name);
    if (p.preset || std::filesystem::exists(std::string(SWARM_PRESET_DIR) + "/" + name)) return p;
    stand_ins.insert(name);
    p = swarm::parse_preset(kGas);
    p.preset->J = 1e-3;
    return p;
  };
  std::string problems;
  const std::vector<Lesson> lessons = load_shipped_lessons(SWARM_LESSON_DIR, lookup, problems);
  CHECK_MESSAGE(problems.empty(), problems);
  CHECK(lessons.size() >= 8);
  std::set<std::string> ids;
  for (const Lesson& l : lessons) {
    CHECK_MESSAGE(ids.insert(l.id).second, l.id);
    CHECK(l.steps.size() >= 4);
  }
  for (const std::string& name : stand_ins) MESSAGE("stand-in for the not yet shipped " << name);
}

TEST_CASE("lesson text without its emphasis marks reads as written") {
  CHECK(without_emphasis("Open *Controls → System*, then *Play*.") ==
        "Open Controls → System, then Play.");
  CHECK(without_emphasis("no marks") == "no marks");
}

TEST_CASE("a lesson carries its own translations, each a text of the lesson in a language the app speaks") {
  ojson l = base_lesson();
  l["steps"][1]["text"] = "{Tap|Click} to pick.";
  l["translations"] = {{"es", {{"Watch *this*.", "Mira *esto*."}, {"{Tap|Click} to pick.", "{Toca|Haz clic} para elegir."},
                               {"no", "no"}, {"T", "T"}}},
                       {"de", {{"it goes up", "es steigt"}}}};
  const LessonParse parsed = parse_lesson(l.dump(), test_lookup);
  REQUIRE_MESSAGE(parsed.lesson, parsed.error);
  const Lesson& lesson = *parsed.lesson;
  REQUIRE(lesson.translation("es", "Watch *this*."));
  CHECK(*lesson.translation("es", "Watch *this*.") == "Mira *esto*.");
  CHECK(*lesson.translation("de", "it goes up") == "es steigt");
  CHECK_FALSE(lesson.translation("de", "Watch *this*."));
  CHECK_FALSE(lesson.translation("fr", "it goes up"));
  const std::vector<std::string> texts = lesson.texts();
  CHECK(std::find(texts.begin(), texts.end(), "Which?") != texts.end());
  CHECK(std::find(texts.begin(), texts.end(), "yes") != texts.end());

  auto with = [&](const ojson& translations) {
    ojson t = l;
    t["translations"] = translations;
    return error_of_json(t);
  };
  CHECK(with({{"ar", {{"T", "x"}}}}) == "translations.ar: not a language the app speaks (es, de, fr, pt-BR, zh-CN)");
  CHECK(with({{"en", {{"T", "x"}}}}).find("translations.en: not a language") == 0);
  CHECK(with({{"es", {{"Not in it", "x"}}}}) ==
        "translations.es.\"Not in it\": not a text of this lesson (the key is the English text, exactly)");
  CHECK(with({{"es", {{"T", ""}}}}) == "translations.es.\"T\" (title): must be a non-empty string");
  CHECK(with({{"es", {{"{Tap|Click} to pick.", "Toca para elegir."}}}}) ==
        "translations.es.\"{Tap|Click} to pick.\" (steps[1].text): must keep the English text's {tap|click} choices, with as many alternatives each");
  CHECK(with({{"es", {{"Watch *this*.", "Mira *esto."}}}}).find("an emphasis is not closed") != std::string::npos);
  CHECK(with(ojson::array()) == "translations: must be an object of language codes (es, de, fr, pt-BR, zh-CN) to tables");
}

TEST_CASE("a translation is held to the rules of the field it translates") {
  ojson l = base_lesson();
  auto with = [&](const char* code, const std::string& english, const std::string& shown) {
    ojson t = l;
    t["translations"] = {{code, {{english, shown}}}};
    return error_of_json(t);
  };
  // A title is at most 120 bytes in every language, as in English; other texts 8,000.
  CHECK(with("de", "T", std::string(120, 'x')) == "");
  CHECK(with("de", "T", std::string(8000, 'x')) ==
        "translations.de.\"T\" (title): must be at most 120 bytes long, as the English is (it has 8000)");
  CHECK(with("fr", "Pick.", std::string(8000, 'x')) == "");
  CHECK(with("fr", "Pick.", std::string(8001, 'x')) ==
        "translations.fr.\"Pick.\" (steps[1].text): must be at most 8000 bytes long, as the English is (it has 8001)");
  // A text in two fields takes the stricter limit: "T" as the title and the summary.
  l["summary"] = "T";
  CHECK(with("es", "T", std::string(121, 'x')).find("(title): must be at most 120 bytes long") != std::string::npos);
  l = base_lesson();
  // Nothing to see is refused, as are DEL and the C1 controls, in the field named.
  CHECK(with("es", "b", "\u202e") ==
        "translations.es.\"b\" (steps[1].task.options[1]): must show something (it holds only spaces or "
        "invisible characters such as U+202E)");
  CHECK(with("zh-CN", "yes", "\u200b\u200c\u200d\u200e\u200f\u202a\u202b\u202c\u202d\u2066\u2067\u2068\u2069\ufeff") ==
        "translations.zh-CN.\"yes\" (steps[1].task.feedback[1]): must show something (it holds only spaces or "
        "invisible characters such as U+200B)");
  CHECK(with("pt-BR", "it goes up", " \u00a0 ") ==
        "translations.pt-BR.\"it goes up\" (steps[2].task.outcome): must show something (it holds only spaces)");
  CHECK(with("de", "Which?", "Welche\x7f?") ==
        "translations.de.\"Which?\" (steps[1].task.prompt): control character U+007F (only line breaks are allowed)");
  CHECK(with("de", "S", "Zusammen\u0090fassung") ==
        "translations.de.\"S\" (summary): control character U+0090 (only line breaks are allowed)");
  // Visible text with a direction mark inside it still reads.
  CHECK(with("de", "Which?", "\u200fWelche?") == "");
}
