#!/usr/bin/env python3
"""Fails when code outside config parsing and the protocol registry spells a protocol's name.

A protocol's name ("paper", "sim", "lcm": the name constants of
experiments/results/protocol_traits.h) may appear as a string literal only in ALLOWED: the traits
catalogue, config parsing (the list of valid names and the default list) and the registry of
built-in protocols. Everything else asks the protocol's traits (TraitsOf, RowTraits) and fills
rows with the name constants (kPaperProtocol, ...), so a new protocol is one catalogue entry and
a changed behaviour one trait, not a hunt through the figures for "== \"sim\"".

Checked: every .h/.hpp/.cpp of the repository outside tests/, build/ and hidden folders, with its
comments removed. A name that also names something else (OTHER_MEANINGS: "lcm" is the middleware,
the folder of event logs and the network label of real-agent rows) is refused only where it is
compared: next to == or !=, or an argument of find/count/contains/Has.

Usage: scripts/check_protocol_names.py [REPO_ROOT]    exit 0: clean, 1: a name spelled, 2: no names
"""
import pathlib
import re
import sys

from source_tree import tree_files

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
TRAITS = "experiments/results/protocol_traits.h"
ALLOWED = {
    TRAITS,
    "experiments/results/protocol_traits.cpp",
    "experiments/config/config.h",
    "experiments/config/config.cpp",
    "experiments/sweep/builtin_protocols.cpp",
}
OTHER_MEANINGS = {"lcm"}
NAME_CONSTANT = re.compile(r'inline\s+constexpr\s+std::string_view\s+k\w+Protocol\s*=\s*"([^"]+)"')
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp")


def protocol_names():
    path = ROOT / TRAITS
    if not path.exists():
        return []
    return NAME_CONSTANT.findall(path.read_text())


def without_comments(text):
    """`text` with its // and /* */ comments blanked (line breaks kept, so line numbers hold);
    string and character literals, raw strings included, are kept as they are."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            i = n if end < 0 else end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:end]))
            i = end
        elif c == "R" and i + 1 < n and text[i + 1] == '"' and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i + 2)
            delimiter = text[i + 2:open_paren]
            end = text.find(")" + delimiter + '"', open_paren)
            end = n if end < 0 else end + len(delimiter) + 2
            out.append(text[i:end])
            i = end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def comparison(name):
    literal = re.escape('"' + name + '"')
    return re.compile(rf'(==|!=)\s*{literal}|{literal}\s*(==|!=)|\b(find|count|contains|Has)\s*\([^;]*{literal}')


def violations(names):
    found = []
    for f in tree_files(ROOT):
        rel = f.relative_to(ROOT)
        if f.suffix not in SOURCE_SUFFIXES or not f.is_file():
            continue
        if rel.parts[0] in ("build", "tests") or rel.parts[0].startswith("."):
            continue
        if rel.as_posix() in ALLOWED:
            continue
        lines = without_comments(f.read_text(errors="replace")).splitlines()
        for number, line in enumerate(lines, 1):
            for name in names:
                literal = '"' + name + '"'
                if literal not in line:
                    continue
                if name in OTHER_MEANINGS and not comparison(name).search(line):
                    continue
                found.append(f"{rel.as_posix()}:{number}: protocol name {literal} outside config parsing and "
                             f"the registry: ask its traits ({TRAITS}: TraitsOf, RowTraits) or use its name "
                             f"constant; {line.strip()}")
    return found


def main():
    names = protocol_names()
    if not names:
        print(f"check_protocol_names: no protocol name constants in {TRAITS}", file=sys.stderr)
        return 2
    found = violations(names)
    for v in found:
        print(v, file=sys.stderr)
    if found:
        return 1
    print(f"check_protocol_names: {', '.join(names)} spelled only in config parsing and the registry")
    return 0


if __name__ == "__main__":
    sys.exit(main())
