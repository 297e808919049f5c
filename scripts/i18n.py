#!/usr/bin/env python3
"""The string tables of assets/i18n/ (docs/i18n.md).

  scripts/i18n.py extract   rewrite assets/i18n/en.json from the sources, the shipped presets
                            and lessons: every text the app shows, as key and value
  scripts/i18n.py check     every table against en.json: each key present, nothing extra, the
                            same printf conversions and device choices, no text left in English
                            (except names); exit 1 with one line per problem
  scripts/i18n.py missing LANG   the keys LANG lacks or has stale, as a JSON object to translate

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
         "Verlet", "Kolmogorov-Smirnov", "Carnahan-Starling", "Appendix A", "Appendix B"}


def is_name(text):
    return not re.search(r"[A-Za-z]{3,}", text) or text.strip() in names


def check():
    english = json.loads((tables / "en.json").read_text())
    problems = []
    current = from_sources() | from_assets()
    if set(english) != current or any(english[k] != k for k in english):
        problems.append(f"en.json is out of date ({len(current - set(english))} texts new, "
                        f"{len(set(english) - current)} gone): run scripts/i18n.py extract")
    for path in sorted(tables.glob("*.json")):
        if path.name == "en.json":
            continue
        table = json.loads(path.read_text())
        code = path.stem
        for key in english:
            if key not in table:
                problems.append(f"{code}: missing: {key[:70]!r}")
                continue
            value = table[key]
            if not isinstance(value, str) or not value.strip():
                problems.append(f"{code}: empty: {key[:70]!r}")
            elif placeholders(value) != placeholders(key):
                problems.append(f"{code}: placeholders differ ({placeholders(key)} in English, "
                                f"{placeholders(value)} here): {key[:60]!r}")
            elif value == key and not is_name(key):
                problems.append(f"{code}: left in English: {key[:70]!r}")
        for key in table:
            if key not in english:
                problems.append(f"{code}: not in en.json (stale): {key[:70]!r}")
    for p in problems:
        print(p)
    print(f"i18n check: {len(english)} keys, {len(list(tables.glob('*.json'))) - 1} languages, "
          f"{len(problems)} problems", file=sys.stderr)
    return 1 if problems else 0


def main():
    command = sys.argv[1] if len(sys.argv) > 1 else "check"
    if command == "extract":
        texts = sorted(from_sources() | from_assets())
        tables.mkdir(parents=True, exist_ok=True)
        (tables / "en.json").write_text(
            json.dumps({t: t for t in texts}, ensure_ascii=False, indent=1) + "\n")
        print(f"assets/i18n/en.json: {len(texts)} texts", file=sys.stderr)
        return 0
    if command == "check":
        return check()
    if command == "missing":
        english = json.loads((tables / "en.json").read_text())
        path = tables / f"{sys.argv[2]}.json"
        table = json.loads(path.read_text()) if path.exists() else {}
        todo = {k: k for k in english if k not in table}
        print(json.dumps(todo, ensure_ascii=False, indent=1))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
