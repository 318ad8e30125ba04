#!/usr/bin/env python3
"""Fails when a source file includes a header of a module it may not use.

The modules and their allowed dependencies are the table in docs/architecture.md
(section "Layers"): one row per module, `| module | folder | may use |`. A file
belongs to the module whose folder is the longest prefix of its path; an include
"x/y/z.h" of a project header belongs to the module of its folder. An include is
allowed within the module and towards the modules its row names (directly, not
through another). Tests are checked too: tests/<module>/ may use <module> and
what it may use (plus tests/ helpers).

Usage: scripts/check_layers.py [REPO_ROOT]    exit 0: clean, 1: violations, 2: bad table
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
DOC = ROOT / "docs" / "architecture.md"
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def read_table():
    """module -> (folder, allowed modules) from the Layers table."""
    text = DOC.read_text()
    start = text.find("## Layers")
    if start < 0:
        sys.exit(f"{DOC}: no '## Layers' section")
    modules = {}
    for line in text[start:].splitlines()[1:]:
        if line.startswith("## "):
            break
        cells = [c.strip().strip("`") for c in line.strip().strip("|").split("|")]
        if len(cells) != 3 or cells[0] in ("module", "") or set(cells[0]) <= {"-", " "}:
            continue
        name, folder, uses = cells
        allowed = {u.strip().strip("`") for u in uses.split(",") if u.strip() and u.strip() != "-"}
        modules[name] = (folder.rstrip("/"), allowed)
    for name, (_, allowed) in modules.items():
        unknown = allowed - modules.keys()
        if unknown:
            print(f"{DOC}: module {name} names unknown modules {sorted(unknown)}", file=sys.stderr)
            sys.exit(2)
    return modules


def module_of(path, modules):
    best, best_len = None, -1
    for name, (folder, _) in modules.items():
        if (path == folder or path.startswith(folder + "/")) and len(folder) > best_len:
            best, best_len = name, len(folder)
    return best


def closure(name, modules):
    """The module itself and everything it may use, directly or through others."""
    seen, todo = set(), [name]
    while todo:
        m = todo.pop()
        if m not in seen:
            seen.add(m)
            todo.extend(modules[m][1])
    return seen


def main():
    modules = read_table()
    violations = []
    for f in sorted(ROOT.rglob("*")):
        if f.suffix not in (".h", ".cpp", ".hpp") or "build" in f.relative_to(ROOT).parts[:1]:
            continue
        rel = f.relative_to(ROOT).as_posix()
        is_test = rel.startswith("tests/")
        owner = module_of(rel[len("tests/"):] if is_test else rel, modules)
        if is_test:
            # tests/<folder>/ tests the module of <folder> or experiments/<folder> (tests/data
            # tests experiments/data; see tests/CMakeLists.txt) and may use what it uses.
            owner = module_of("experiments/" + rel[len("tests/"):], modules) or owner
        if owner is None:
            continue
        allowed = closure(owner, modules) if is_test else {owner} | modules[owner][1]
        for line_no, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = module_of(m.group(1), modules)
            if target is None or target in allowed:
                continue
            violations.append(f"{rel}:{line_no}: {owner} includes {m.group(1)} of {target}, "
                              f"which {owner} may not use (docs/architecture.md, Layers)")
    for v in violations:
        print(v, file=sys.stderr)
    if violations:
        print(f"check_layers: {len(violations)} include(s) against the layering", file=sys.stderr)
        return 1
    print(f"check_layers: {len(modules)} modules, no include against the layering", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
