#!/usr/bin/env python3
"""The string tables of assets/i18n/ (docs/i18n.md).

  scripts/i18n.py extract   rewrite assets/i18n/en.json from the sources, the shipped presets
                            and lessons: every text the app shows, as key and value
  scripts/i18n.py check [DIR]  every table (of assets/i18n/, or DIR) against en.json: each key
                            present, nothing extra, the same printf conversions and device
                            choices, no text left in English (except names), each translation
                            held to its English field's rules (a lesson title at most 120 bytes,
                            something visible, no control character but a line break); exit 1
                            with one line per problem
  scripts/i18n.py missing LANG   the keys LANG lacks or has stale, as a JSON object to translate
  scripts/i18n.py page OUT  write OUT (build/web/page_texts.js): the language table (each
                            language's code, decimal separator, aliases, whether it is the
                            pseudo-language), and for each table only the keys the page itself
                            uses (pageText('...') in web/*.js and web/shell.html)

The languages are the rows of assets/i18n/languages.json, the one table the C++ (built in,
app/i18n/language_table.cpp) and the page (through `page`) read; `check` and `page` refuse a
malformed one, naming the row and the field.

The keys are the English texts themselves (as gettext's msgid): tr("Pause") in the C++ and
"Pause" in the table. A string's English changing leaves its old translations stale: `check`
names them, and the app shows the English until they are translated again.
"""
import json
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
tables = root / "assets" / "i18n"
sources = [root / "app" / "ui", root / "app" / "access", root / "app" / "labels", root / "app" / "lessons",
           root / "web"]

# tr("..."), tr_id("...") and tr_noop("..."): one or more adjacent literals, as C++ joins them.
call = re.compile(r'\btr(?:_id|_noop)?\s*\(\s*((?:"(?:[^"\\\n]|\\.)*"\s*)+)\)')
literal = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
escape = re.compile(r'\\(u[0-9a-fA-F]{4}|U[0-9a-fA-F]{8}|x[0-9a-fA-F]{1,2}|[0-7]{1,3}|.)')
simple = {"n": "\n", "t": "\t", '"': '"', "'": "'", "\\": "\\", "?": "?", "a": "\a", "0": "\0"}


def unescape(text):
    """A C++ string literal's body as the string it stands for (UTF-8 source)."""
    raw = bytearray()
    pos = 0
    for m in escape.finditer(text):
        raw += text[pos:m.start()].encode()
        e = m.group(1)
        if e[0] in "uU":
            raw += chr(int(e[1:], 16)).encode()
        elif e[0] == "x":
            raw.append(int(e[1:], 16))
        elif e[0].isdigit() and e != "0":
            raw.append(int(e, 8))
        else:
            raw += simple.get(e, e).encode()
        pos = m.end()
    raw += text[pos:].encode()
    return raw.decode()


def visible(label):
    """What an ImGui label shows: the text before "##"."""
    return label.split("##", 1)[0]


def from_sources():
    found = set()
    for folder in sources:
        for path in sorted(folder.rglob("*")):
            if path.suffix not in (".cpp", ".h"):
                continue
            for m in call.finditer(path.read_text()):
                text = visible("".join(unescape(b) for b in literal.findall(m.group(1))))
                if text.strip():
                    found.add(text)
    return found


fields = ("code", "native_name", "decimal_separator", "aliases", "pseudo", "font", "same_as_english")
fonts = ("DejaVu Sans", "Noto Sans CJK SC")  # the UI's font; Chinese glyphs (app/ui/platform/fonts.cpp)
language_tag = re.compile(r"[A-Za-z]{1,8}(-[A-Za-z0-9]{1,8})*")
primary_subtag = re.compile(r"[a-z]{2,3}")


class BadTable(Exception):
    pass


def read_languages(folder=tables):
    """The rows of FOLDER/languages.json, checked by the rules of app/i18n/language_table.cpp:
    BadTable names the row, the field and the rule."""
    path = folder / "languages.json"
    try:
        rows = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        raise BadTable(f"{path.name}: not valid JSON ({e})")
    if not isinstance(rows, list) or not rows:
        raise BadTable(f"{path.name}: must be a JSON array of languages, one object each, the language of "
                       "the texts first")
    aliases = {}
    for i, row in enumerate(rows):
        where = f"{path.name}: [{i}]"
        if not isinstance(row, dict):
            raise BadTable(f"{where}: must be an object with the fields {', '.join(fields)}")
        for name in row:
            if name not in fields:
                raise BadTable(f"{where}.{name}: not a field of a language ({', '.join(fields)})")
        for name in fields:
            if name not in row:
                raise BadTable(f"{where}.{name}: missing (every language has all seven fields)")
        code = row["code"]
        if not isinstance(code, str) or not language_tag.fullmatch(code):
            raise BadTable(f"{where}.code: must be a BCP 47 language tag (parts of 1 to 8 letters or digits "
                           "joined by '-', the first of letters)")
        if any(r["code"] == code for r in rows[:i]):
            raise BadTable(f"{where}.code: {code!r} is another row's code already")
        if not isinstance(row["native_name"], str) or not row["native_name"] or control_character(row["native_name"]):
            raise BadTable(f"{where}.native_name: must be the language's name as its readers write it")
        if row["decimal_separator"] not in (".", ","):
            raise BadTable(f"{where}.decimal_separator: must be \".\" or \",\"")
        if not isinstance(row["aliases"], list):
            raise BadTable(f"{where}.aliases: must be an array of primary language subtags such as [\"pt\"]")
        for k, alias in enumerate(row["aliases"]):
            if not isinstance(alias, str) or not primary_subtag.fullmatch(alias):
                raise BadTable(f"{where}.aliases[{k}]: must be a primary language subtag in lower case, 2 or 3 letters")
            if alias in aliases:
                raise BadTable(f"{where}.aliases: {alias!r} is an alias of {aliases[alias]} already")
            aliases[alias] = code
        if not isinstance(row["pseudo"], bool):
            raise BadTable(f"{where}.pseudo: must be true or false")
        if row["pseudo"] and row["aliases"]:
            raise BadTable(f"{where}.aliases: must be [] for the pseudo-language, which only its code chooses")
        if row["font"] not in fonts:
            raise BadTable(f"{where}.font: must be one of {', '.join(fonts)}")
        if not isinstance(row["same_as_english"], list) or not all(isinstance(t, str) for t in row["same_as_english"]):
            raise BadTable(f"{where}.same_as_english: must be an array of English texts")
    pseudo = [i for i, r in enumerate(rows) if r["pseudo"]]
    if len(pseudo) != 1 or pseudo[0] == 0:
        raise BadTable(f"{path.name}: pseudo: one language, not the first, must be the pseudo-language")
    return rows


def translations(rows):
    """The languages with a table of their own: neither the first (its texts are the keys) nor
    the pseudo-language (it makes its texts)."""
    return [r for r in rows[1:] if not r["pseudo"]]


# pageText('...') and pageText("..."): the page's own texts (web/page_text.js), one literal each.
page_call = re.compile(r"""\bpageText\s*\(\s*('(?:[^'\\\n]|\\.)*'|"(?:[^"\\\n]|\\.)*")\s*[,)]""")
page_files = ["web/*.js", "web/shell.html"]


def from_page():
    found = set()
    for pattern in page_files:
        for path in sorted(root.glob(pattern)):
            for m in page_call.finditer(path.read_text()):
                text = unescape(m.group(1)[1:-1])
                if text.strip():
                    found.add(text)
    return found


def page_tables(out):
    """Writes the page's part of assets/i18n (a few KB, loaded before web/page_text.js and the
    wasm): window.swarmlabLanguages, the rows of languages.json the page needs, and
    window.swarmlabPageTexts = {code: {english: text}}, each table with only the keys the page uses."""
    rows = read_languages()
    languages = [{k: r[k] for k in ("code", "decimal_separator", "aliases", "pseudo")} for r in rows]
    keys = from_page()
    page = {}
    for row in translations(rows):
        table = json.loads((tables / f"{row['code']}.json").read_text())
        page[row["code"]] = {k: table[k] for k in sorted(keys) if isinstance(table.get(k), str) and table[k]}
    text = ("// Generated by scripts/i18n.py page from assets/i18n/: the languages (languages.json) and the\n"
            "// page's own texts in each (web/page_text.js reads both).\n"
            "window.swarmlabLanguages = " + json.dumps(languages, ensure_ascii=False) + ";\n"
            "window.swarmlabPageTexts = " +
            json.dumps(page, ensure_ascii=False, indent=0, sort_keys=True) + ";\n")
    out = pathlib.Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    if not out.exists() or out.read_text() != text:
        out.write_text(text)
    print(f"{out}: {len(keys)} page texts, {len(page)} languages", file=sys.stderr)


def lesson_texts(lesson):
    yield lesson.get("title", "")
    yield lesson.get("summary", "")
    for step in lesson.get("steps", []):
        yield step.get("text", "")
        task = step.get("task") or {}
        yield task.get("prompt", "")
        yield task.get("outcome", "")
        yield from task.get("options", [])
        yield from task.get("feedback", [])
        preset = step.get("preset")
        if isinstance(preset, dict):
            yield preset.get("name", "")
            yield preset.get("description", "")


def from_assets():
    found = set()
    for path in sorted((root / "assets" / "presets").glob("*.json")):
        preset = json.loads(path.read_text())
        found.update([preset.get("name", ""), preset.get("description", "")])
    for path in sorted((root / "assets" / "lessons").glob("*.json")):
        found.update(lesson_texts(json.loads(path.read_text())))
    return {t for t in found if t.strip()}


conversion = re.compile(r"%[-+#0-9.*hlLzjt]*[a-zA-Z%]")  # "15 % of" is prose, not a conversion
choice = re.compile(r"\{[^{}\n]*\|[^{}\n]*\}")


def placeholders(text):
    """What a translation must keep: printf conversions in order, and how many device choices
    with how many alternatives each ({tap|click} is a choice of two)."""
    return (conversion.findall(text), [c.count("|") + 1 for c in choice.findall(text)])


# Texts that read the same in every language: names of people, methods, formats and the app. A
# value equal to its key is accepted for these and for any text without a word of three letters.
names = {"Swarm Lab", "CSV", "PNG", "SVG", "JSON", "OK", "FPS", "Euler", "Euler-Cromer", "RK4",
         "Verlet", "Kolmogorov-Smirnov", "Carnahan-Starling",
         # keys as printed on keyboards, and symbols written out
         "Ctrl +", "Ctrl -", "F6, Ctrl+F6", "Shift+F6", "Home", "End", "Esc", "gamma", "tau",
         "[log]", "factor"}


# A lesson's title is at most this long in every language (app/lessons/lesson.cpp).
max_title_bytes = 120


def lesson_titles():
    return {json.loads(p.read_text()).get("title", "") for p in (root / "assets" / "lessons").glob("*.json")}


def control_character(text):
    """The first control character but a line break (C0, DEL or C1), as U+XXXX, or None."""
    for c in text:
        if (ord(c) < 0x20 and c != "\n") or 0x7F <= ord(c) <= 0x9F:
            return f"U+{ord(c):04X}"
    return None


# Characters that draw nothing (app/lessons/lesson.cpp's draws_nothing): spaces, direction
# marks and embeddings, zero-width characters, the soft hyphen, invisible operators, tags and
# the Hangul fillers.
invisible = re.compile("[\\s\u00ad\u034f\u061c\u115f\u1160\u180e\u200b-\u200f\u202a-\u202e"
                       "\u2060-\u206f\u3164\ufeff\uffa0\U000e0000-\U000e007f]*")


def draws_nothing(text):
    return invisible.fullmatch(text) is not None


def is_name(text, same_as_english=()):
    """Whether a text may read the same as its English: a name, a text without a word of three
    letters, or one of the words the language writes as English does (languages.json's
    same_as_english, checked by the second reading, docs/i18n.md)."""
    return (not re.search(r"[A-Za-z]{3,}", text) or text.strip() in names
            or text.strip() in same_as_english)


def check(folder=tables):
    try:
        rows = read_languages(folder)
    except BadTable as e:
        print(e)
        return 1
    source = rows[0]["code"]
    english = json.loads((folder / f"{source}.json").read_text())
    problems = []
    current = from_sources() | from_assets() | from_page()
    if set(english) != current or any(english[k] != k for k in english):
        problems.append(f"{source}.json is out of date ({len(current - set(english))} texts new, "
                        f"{len(set(english) - current)} gone): run scripts/i18n.py extract")
    files = {p.stem for p in folder.glob("*.json")} - {"languages"}
    listed = {r["code"] for r in rows if not r["pseudo"]}
    for code in sorted(listed - files):
        problems.append(f"{code}: in languages.json, but {code}.json is missing")
    for code in sorted(files - listed):
        problems.append(f"{code}.json: not a language of languages.json (add its row)")
    titles = lesson_titles()
    for row in translations(rows):
        code = row["code"]
        path = folder / f"{code}.json"
        if not path.exists():
            continue
        table = json.loads(path.read_text())
        for key in english:
            if key not in table:
                problems.append(f"{code}: missing: {key[:70]!r}")
                continue
            value = table[key]
            if not isinstance(value, str) or not value.strip():
                problems.append(f"{code}: empty: {key[:70]!r}")
            elif draws_nothing(value):
                problems.append(f"{code}: shows nothing (only spaces or invisible characters such as "
                                f"U+{ord(value.strip()[0]):04X}): {key[:60]!r}")
            elif control_character(value) and not control_character(key):
                problems.append(f"{code}: control character {control_character(value)} (only line breaks "
                                f"are allowed): {key[:60]!r}")
            elif key in titles and len(value.encode()) > max_title_bytes:
                problems.append(f"{code}: a lesson title, at most {max_title_bytes} bytes as in English "
                                f"(it has {len(value.encode())}): {key[:60]!r}")
            elif placeholders(value) != placeholders(key):
                problems.append(f"{code}: placeholders differ ({placeholders(key)} in English, "
                                f"{placeholders(value)} here): {key[:60]!r}")
            elif value == key and not is_name(key, row["same_as_english"]):
                problems.append(f"{code}: left in English: {key[:70]!r}")
        for key in table:
            if key not in english:
                problems.append(f"{code}: not in en.json (stale): {key[:70]!r}")
    for p in problems:
        print(p)
    print(f"i18n check: {len(english)} keys, {len(translations(rows))} translations, "
          f"{len(problems)} problems", file=sys.stderr)
    return 1 if problems else 0


def main():
    command = sys.argv[1] if len(sys.argv) > 1 else "check"
    if command == "extract":
        texts = sorted(from_sources() | from_assets() | from_page())
        source = read_languages()[0]["code"]
        (tables / f"{source}.json").write_text(
            json.dumps({t: t for t in texts}, ensure_ascii=False, indent=1) + "\n")
        print(f"assets/i18n/{source}.json: {len(texts)} texts", file=sys.stderr)
        return 0
    if command == "check":
        return check(pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else tables)
    if command == "page" and len(sys.argv) > 2:
        try:
            page_tables(sys.argv[2])
        except BadTable as e:
            print(f"scripts/i18n.py page: assets/i18n/{e}", file=sys.stderr)
            return 1
        return 0
    if command == "missing":
        english = json.loads((tables / f"{read_languages()[0]['code']}.json").read_text())
        path = tables / f"{sys.argv[2]}.json"
        table = json.loads(path.read_text()) if path.exists() else {}
        todo = {k: k for k in english if k not in table}
        print(json.dumps(todo, ensure_ascii=False, indent=1))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
