#!/usr/bin/env python3
"""Subsets of Noto Sans CJK SC (Debian's fonts-noto-cjk) holding only the characters Swarm Lab
shows, made with pyftsubset (Debian's fonttools) at build time (docs/i18n.md):

  NAMES: the characters of the languages' own names (languages.json's native_name: the View >
         Language menu shows "中文（简体）" in every language), a few kB built into every binary;
  SUBSET: every character of the tables of the languages whose font is Noto Sans CJK SC (in
         languages.json), plus those, loaded only for such a language.

Usage: cjk_font_subset.py TABLE_DIR NAMES.otf SUBSET.otf
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

SOURCE = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc"
SC = 2  # the collection's fonts: JP, KR, SC, TC, HK, then the Mono ones


def wide(text):
    """The characters beyond Latin-1, Greek and the symbols DejaVu Sans draws."""
    return {c for c in text if ord(c) >= 0x2E80}


def subset(characters, out):
    # The build's generated/ folder may not exist yet when this is the first thing made in it.
    pathlib.Path(out).parent.mkdir(parents=True, exist_ok=True)
    with tempfile.NamedTemporaryFile("w", suffix=".txt", encoding="utf-8", delete=False) as f:
        f.write("".join(sorted(characters)) or "中")
    subprocess.run(["pyftsubset", SOURCE, f"--font-number={SC}", f"--text-file={f.name}",
                    f"--output-file={out}", "--no-hinting", "--layout-features=",
                    "--name-IDs=*", "--notdef-outline"], check=True)
    pathlib.Path(f.name).unlink()


def main():
    tables, names_out, subset_out = sys.argv[1:4]
    if not pathlib.Path(SOURCE).exists():
        sys.exit(f"cjk_font_subset: {SOURCE} is missing (apt-get install fonts-noto-cjk fonttools, "
                 "or scripts/deps.sh desktop)")
    # The table is checked where it is read (scripts/i18n.py, app/i18n/language_table.cpp).
    languages = json.loads((pathlib.Path(tables) / "languages.json").read_text(encoding="utf-8"))
    names = set().union(*(wide(l["native_name"]) for l in languages))
    chinese = set()
    for language in languages:
        table = pathlib.Path(tables) / f"{language['code']}.json"
        if language["font"] == "Noto Sans CJK SC" and table.exists():
            for value in json.loads(table.read_text(encoding="utf-8")).values():
                chinese |= wide(value)
    subset(names, names_out)
    subset(names | chinese, subset_out)
    print(f"cjk_font_subset: {len(names)} name characters, {len(names | chinese)} in all",
          file=sys.stderr)


if __name__ == "__main__":
    main()
