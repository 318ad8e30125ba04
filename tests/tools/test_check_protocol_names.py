#!/usr/bin/env python3
"""scripts/check_protocol_names.py refuses a protocol's name spelled outside config parsing and
the registry, and only that.

In a scratch tree holding the checker and the traits header (the names' one home), plants one
file at a time and checks the exit status and, when refused, that the message names the file,
line and literal:
1. refused: a comparison with "sim" in the figures, the names iterated as a list, a find() for
   "paper" in the sweep, a comparison with "lcm";
2. accepted: a name in a comment, a name in config.cpp and in the registry, "lcm" as a folder
   name (not compared), a comparison in tests/;
3. exit 2 when the traits header names no protocol.
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
TRAITS = "experiments/results/protocol_traits.h"


def run(root):
    r = subprocess.run([sys.executable, str(root / "scripts/check_protocol_names.py"), str(root)],
                       capture_output=True, text=True)
    return r.returncode, r.stderr


def planted(root, rel, text, want_code, want=None):
    path = root / rel
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    code, err = run(root)
    path.unlink()
    assert code == want_code, f"{rel}: exit {code}, expected {want_code}\n{err}"
    if want is not None:
        assert want in err, f"{rel}: no '{want}' in\n{err}"


def main():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "scripts").mkdir()
        shutil.copy(SOURCE / "scripts/check_protocol_names.py", root / "scripts")
        shutil.copy(SOURCE / "scripts/source_tree.py", root / "scripts")
        (root / TRAITS).parent.mkdir(parents=True)
        shutil.copy(SOURCE / TRAITS, root / TRAITS)
        code, err = run(root)
        assert code == 0, f"clean tree: exit {code}\n{err}"

        figures = "experiments/figures/planted.cpp"
        planted(root, figures, 'bool F(const R& r) {\n  return r.key.protocol == "sim";\n}\n', 1,
                f'{figures}:2: protocol name "sim"')
        planted(root, figures, 'void F() {\n  for (const char* p : {"paper", "sim"}) G(p);\n}\n', 1,
                f'{figures}:2: protocol name "paper"')
        planted(root, "experiments/sweep/planted.cpp",
                'bool F(const V& v) {\n  // a comment\n  return std::find(v.begin(), v.end(), "paper") != v.end();\n}\n', 1,
                'experiments/sweep/planted.cpp:3: protocol name "paper"')
        planted(root, figures, 'bool F(const R& r) { return "lcm" == r.key.protocol; }\n', 1,
                f'{figures}:1: protocol name "lcm"')

        planted(root, figures, '// rows of protocol "sim" and "paper"\n/* "sim" */ int x;\n', 0)
        planted(root, "experiments/config/config.cpp", 'static const char* names[] = {"paper", "sim"};\n', 0)
        planted(root, "experiments/sweep/builtin_protocols.cpp", 'bool F(const S& s) { return s == "sim"; }\n', 0)
        planted(root, "experiments/protocols/sim/planted.cpp", 'auto d = out_dir / "lcm";\n', 0)
        planted(root, "tests/figures/test_planted.cpp", 'bool F(const R& r) { return r.protocol == "sim"; }\n', 0)

        (root / TRAITS).write_text("// no names\n")
        code, err = run(root)
        assert code == 2, f"no name constants: exit {code}, expected 2\n{err}"
    print("check_protocol_names refuses 4 planted comparisons and accepts 5 allowed spellings")


if __name__ == "__main__":
    main()
