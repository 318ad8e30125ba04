#!/usr/bin/env python3
"""Fails when the code or its CMake links go against the layers of docs/architecture.md.

The modules are the "Layers" table of docs/architecture.md: one row per module,
`| module | folder | may use | packages |`; the packages (CMake targets outside the project) and
the headers that are theirs are the "Packages" table, `| package | headers |`. A file belongs to
the module whose folder is the longest prefix of its path. Checked:

1. Includes. A quoted include "x/y/z.h" of a project header belongs to the module of its folder;
   an angle-bracket include belongs to a package when it matches one of the package's headers
   (`lcm/` a folder, `mpi.h` a file), and `<dvpr/T.hpp>` to dvpr_lcmtypes when
   lcmtypes/dvpr/T.lcm exists (lcm-gen's code). Other angle-bracket includes are the system's.
   A file may include its own module and what its row names, directly. Tests are checked too:
   tests/<folder>/ may use the modules its executable links (dvpr_test in tests/CMakeLists.txt:
   the tested module, and any other it checks against), what they may use through any number
   of rows, their packages, and GoogleTest.
2. CMake. A module's calls in its folder's CMakeLists.txt (dvpr_module PUBLIC/PRIVATE/DEPS,
   target_link_libraries, or the LIBS of dvpr_executable for a folder of executables) link
   exactly what its row names, modules and packages.
3. PUBLIC only where a header needs it. A module or package a header of the module includes is
   linked PUBLIC (whoever includes that header compiles it); one only its .cpp files include is
   linked PRIVATE. (Not for a folder of executables: nothing links them.)
4. Nothing unused. Every module and package a row names is included by some file of the module
   (packages whose headers are "-", such as Threads::Threads, excepted).
5. Kept apart. The "Kept apart" table, `| module | never reaches |`: nothing in the module's
   closure (what it may use, through any number of rows, and their packages) is one of those
   named, so that, say, the evaluation never links liblcm.
6. Tiers. The "Tiers" table, `| tier | folders |`, lowest first: a module of a tier may use
   modules of its own tier and those below, never one above (the domain code of a simulation
   never reaches the runner); every module under experiments/ is in a tier.

Usage: scripts/check_layers.py [REPO_ROOT]    exit 0: clean, 1: violations, 2: bad table
"""
import pathlib
import re
import sys

from source_tree import tree_files

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
DOC = ROOT / "docs" / "architecture.md"
DOC_NAME = "docs/architecture.md"
QUOTED = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
ANGLED = re.compile(r'^\s*#\s*include\s+<([^>]+)>')
LCM_TYPE = re.compile(r"^dvpr/(\w+)\.hpp$")
TEST_PACKAGES = {"GTest::gtest": ["gtest/", "gmock/"]}  # every test links GoogleTest
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp")
HEADER_SUFFIXES = (".h", ".hpp")


class BadTable(Exception):
    pass


def names(cell):
    return {u.strip().strip("`") for u in cell.split(",") if u.strip().strip("`") not in ("", "-")}


def table_rows(text, heading):
    """The cells of each row of the first table under `## heading`."""
    start = text.find("## " + heading)
    if start < 0:
        raise BadTable(f"{DOC_NAME}: no '## {heading}' section")
    rows = []
    for line in text[start:].splitlines()[1:]:
        if line.startswith("## "):
            break
        if not line.startswith("|"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if set("".join(cells)) <= {"-", " ", ":"} or cells[0] in ("module", "package", "tier"):
            continue
        rows.append(cells)
    return rows


def read_tables():
    """modules: name -> {folder, uses, packages}; packages: name -> header patterns."""
    text = DOC.read_text()
    modules = {}
    for cells in table_rows(text, "Layers"):
        if len(cells) != 4:
            raise BadTable(f"{DOC_NAME}: Layers row needs 4 cells (module, folder, may use, packages): {cells}")
        name, folder, uses, packages = cells
        modules[name.strip("`")] = {"folder": folder.strip("`").rstrip("/"), "uses": names(uses),
                                    "packages": names(packages)}
    packages = {}
    for cells in table_rows(text, "Packages"):
        if len(cells) != 2:
            raise BadTable(f"{DOC_NAME}: Packages row needs 2 cells (package, headers): {cells}")
        packages[cells[0].strip("`")] = sorted(names(cells[1]))
    for name, m in modules.items():
        unknown = m["uses"] - modules.keys()
        if unknown:
            raise BadTable(f"{DOC_NAME}: module {name} names unknown modules {sorted(unknown)}")
        unknown = m["packages"] - packages.keys()
        if unknown:
            raise BadTable(f"{DOC_NAME}: module {name} names packages {sorted(unknown)} the Packages table does not")
    return modules, packages


def module_of(path, modules):
    best, best_len = None, -1
    for name, m in modules.items():
        folder = m["folder"]
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
            todo.extend(modules[m]["uses"])
    return seen


def package_of(header, packages):
    """The package a header is of: one naming the file itself before one naming its folder."""
    exact = [n for n, patterns in packages.items() if header in patterns]
    if exact:
        return exact[0]
    for name, patterns in packages.items():
        for p in patterns:
            if p.endswith("/") and header.startswith(p):
                return name
    return None


def target_of(line, modules, packages):
    """(include, module or package) of an #include line; None when it names neither."""
    m = QUOTED.match(line)
    if m:
        return m.group(1), module_of(m.group(1), modules) or package_of(m.group(1), packages)
    m = ANGLED.match(line)
    if not m:
        return None
    header = m.group(1)
    t = LCM_TYPE.match(header)
    if t and (ROOT / "lcmtypes" / "dvpr" / (t.group(1) + ".lcm")).exists():
        return header, "dvpr_lcmtypes"
    return header, package_of(header, packages)


def source_files():
    for f in tree_files(ROOT):
        rel = f.relative_to(ROOT)
        if f.suffix in SOURCE_SUFFIXES and rel.parts[0] != "build" and not rel.parts[0].startswith("."):
            yield f, rel.as_posix()


def strip_cmake_comments(text):
    return "\n".join(line.split("#", 1)[0] for line in text.splitlines())


def cmake_calls(text, command):
    """Each call of `command` as a list of its arguments."""
    return [c.split() for c in re.findall(rf"\b{command}\(([^)]*)\)", strip_cmake_comments(text))]


def keyword_lists(args, keywords):
    """Splits `args` at the keywords: keyword -> the arguments after it."""
    out, current = {k: [] for k in keywords}, None
    for a in args:
        if a in keywords:
            current = a
        elif current is not None:
            out[current].append(a)
    return out


def cmake_links(module, folder):
    """(CMakeLists.txt path, public, private) as that file links `module`; None without a file."""
    path = ROOT / folder / "CMakeLists.txt"
    if not path.exists():
        return None
    text = path.read_text()
    public, private, found = set(), set(), False
    for args in cmake_calls(text, "dvpr_module"):
        if args and args[0] == module:
            found = True
            kw = keyword_lists(args[1:], ("PUBLIC", "PRIVATE", "DEPS", "DEFINITIONS"))
            public |= set(kw["PUBLIC"]) | set(kw["DEPS"])
            private |= set(kw["PRIVATE"])
    for args in cmake_calls(text, "target_link_libraries"):
        if args and args[0] == module:
            found = True
            kw = keyword_lists(args[1:], ("PUBLIC", "PRIVATE", "INTERFACE"))
            public |= set(kw["PUBLIC"]) | set(kw["INTERFACE"])
            private |= set(kw["PRIVATE"])
    executables = not found
    if executables:  # a folder of executables (bench/): what they link, nothing passes on
        for args in cmake_calls(text, "dvpr_executable"):
            private |= set(keyword_lists(args[1:], ("SOURCES", "LIBS", "DEFINITIONS", "OUTPUT_DIR"))["LIBS"])
    skip = {"dvpr_includes", "dvpr_warnings"}  # every module's: include path and warnings
    clean = lambda s: {t for t in s if "$" not in t and t not in skip}
    return path.relative_to(ROOT).as_posix(), clean(public), clean(private), executables


def test_modules(modules):
    """tests/<folder> -> the modules its test executable links (dvpr_test in tests/CMakeLists.txt:
    the tested module first, then any other it checks against)."""
    path = ROOT / "tests" / "CMakeLists.txt"
    tested = {}
    if path.exists():
        for args in cmake_calls(path.read_text(), "dvpr_test"):
            if len(args) >= 2 and args[0] != "folder" and all(a in modules for a in args[1:]):
                tested["tests/" + args[0]] = args[1:]
    return tested


def test_owner(rel, modules, tested):
    """The modules a test file may use the closure of: its folder's dvpr_test, else the module of
    tests/<folder> read as <folder> or experiments/<folder>."""
    best = max((f for f in tested if rel.startswith(f + "/")), key=len, default=None)
    if best is not None:
        return tested[best]
    sub = rel[len("tests/"):]
    owner = module_of("experiments/" + sub, modules) or module_of(sub, modules)
    return [owner] if owner else []


def check_includes(modules, packages, uses_seen, header_needs):
    """Rule 1; fills uses_seen (module -> targets its files include) and header_needs (module ->
    {target: "file:line"} its headers include)."""
    violations = []
    tested = test_modules(modules)
    for f, rel in source_files():
        is_test = rel.startswith("tests/")
        if is_test:
            linked = test_owner(rel, modules, tested)
            if not linked:
                continue
            owner = linked[0]
            allowed = set().union(*(closure(m, modules) for m in linked))
            allowed |= {p for m in allowed for p in modules[m]["packages"]} | set(TEST_PACKAGES)
        else:
            owner = module_of(rel, modules)
            if owner is None:
                continue
            allowed = {owner} | modules[owner]["uses"] | modules[owner]["packages"]
        for line_no, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
            found = target_of(line, modules, {**packages, **TEST_PACKAGES})
            if found is None or found[1] is None:
                continue
            header, target = found
            if target not in allowed:
                violations.append(f"{rel}:{line_no}: {owner} includes {header} of {target}, "
                                  f"which {owner} may not use ({DOC_NAME}, Layers)")
                continue
            if is_test or target == owner:
                continue
            uses_seen.setdefault(owner, set()).add(target)
            if f.suffix in HEADER_SUFFIXES:
                header_needs.setdefault(owner, {}).setdefault(target, f"{rel}:{line_no}")
    return violations


def check_cmake(modules, packages, uses_seen, header_needs):
    """Rules 2, 3 and 4."""
    violations = []
    if any((ROOT / "lcmtypes" / "dvpr").glob("*.lcm")):
        # lcm-gen's headers (in the build tree) include <lcm/lcm_coretypes.h>.
        lcm = package_of("lcm/lcm_coretypes.h", packages)
        if lcm is not None and "dvpr_lcmtypes" in modules:
            uses_seen.setdefault("dvpr_lcmtypes", set()).add(lcm)
            header_needs.setdefault("dvpr_lcmtypes", {})[lcm] = "lcm-gen's code"
    for name, m in modules.items():
        row = m["uses"] | m["packages"]
        unused = {t for t in row - uses_seen.get(name, set()) if t in modules or packages.get(t)}
        for t in sorted(unused):
            violations.append(f"{DOC_NAME}: {name} may use {t}, but no file of {m['folder']}/ includes it: "
                              f"drop it from the row and the CMake links")
        links = cmake_links(name, m["folder"])
        if links is None:
            violations.append(f"{m['folder']}/CMakeLists.txt: missing; {name} has a row in {DOC_NAME}")
            continue
        path, public, private, executables = links
        linked = public | private
        for t in sorted(row - linked):
            violations.append(f"{path}: {name} does not link {t}, which its row of {DOC_NAME} names")
        for t in sorted(linked - row):
            violations.append(f"{path}: {name} links {t}, which its row of {DOC_NAME} does not name")
        if executables:
            continue
        needs = header_needs.get(name, {})
        for t in sorted(set(needs) - public):
            if t in linked:
                violations.append(f"{path}: {name} links {t} PRIVATE, but its header includes it "
                                  f"({needs[t]}): link it PUBLIC")
        has_sources = any((ROOT / m["folder"]).glob("*.cpp"))  # else all it links is PUBLIC
        for t in sorted(public - set(needs)):
            if has_sources and t in row and (t in modules or packages.get(t)):
                violations.append(f"{path}: {name} links {t} PUBLIC, but none of its headers includes it: "
                                  f"link it PRIVATE")
    return violations


def check_kept_apart(modules, packages):
    """Rule 5."""
    violations = []
    for cells in table_rows(DOC.read_text(), "Kept apart"):
        if len(cells) != 2:
            raise BadTable(f"{DOC_NAME}: Kept apart row needs 2 cells (module, never reaches): {cells}")
        name, never = cells[0].strip("`"), names(cells[1])
        unknown = ({name} | never) - modules.keys() - packages.keys()
        if unknown:
            raise BadTable(f"{DOC_NAME}: Kept apart names unknown {sorted(unknown)}")
        reach = closure(name, modules)
        reach |= {p for m in reach for p in modules[m]["packages"]}
        for t in sorted(never & reach):
            path = next(m for m in sorted(closure(name, modules))
                        if t == m or t in modules[m]["packages"])
            violations.append(f"{DOC_NAME}: {name} reaches {t} (through {path}), which Kept apart forbids")
    return violations


def check_tiers(modules):
    """Rule 6."""
    text = DOC.read_text()
    tiers = []
    for cells in table_rows(text, "Tiers"):
        if len(cells) != 2:
            raise BadTable(f"{DOC_NAME}: Tiers row needs 2 cells (tier, folders): {cells}")
        tiers.append((cells[0], {f.rstrip("/") for f in names(cells[1])}))

    def tier_of(folder):
        best, best_len = None, -1
        for i, (_, folders) in enumerate(tiers):
            for f in folders:
                if (folder == f or folder.startswith(f + "/")) and len(f) > best_len:
                    best, best_len = i, len(f)
        return best

    violations = []
    for name, m in sorted(modules.items()):
        t = tier_of(m["folder"])
        if t is None:
            if m["folder"].startswith("experiments/"):
                violations.append(f"{DOC_NAME}: {name} ({m['folder']}/) is in no tier: add its folder to Tiers")
            continue
        for u in sorted(m["uses"]):
            tu = tier_of(modules[u]["folder"])
            if tu is not None and tu > t:
                violations.append(f"{DOC_NAME}: {name} ({tiers[t][0]} tier) may use {u} of the {tiers[tu][0]} "
                                  f"tier above it (Tiers)")
    return violations


def main():
    try:
        modules, packages = read_tables()
    except BadTable as e:
        print(e, file=sys.stderr)
        return 2
    uses_seen, header_needs = {}, {}
    violations = check_includes(modules, packages, uses_seen, header_needs)
    violations += check_cmake(modules, packages, uses_seen, header_needs)
    try:
        violations += check_kept_apart(modules, packages)
        violations += check_tiers(modules)
    except BadTable as e:
        print(e, file=sys.stderr)
        return 2
    for v in violations:
        print(v, file=sys.stderr)
    if violations:
        print(f"check_layers: {len(violations)} violation(s) of the layering", file=sys.stderr)
        return 1
    print(f"check_layers: {len(modules)} modules, includes and CMake links follow the layering", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
