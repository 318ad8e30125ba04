#!/usr/bin/env python3
"""scripts/check_doc_commands.py runs the docs' commands as written and refuses a broken one.

Writes small markdown files into a scratch folder and runs the checker on them, with the
repository's configs and the given dvpr:
1. a doc whose commands are right passes: a fenced `dvpr run` continued over two lines, a
   `dvpr plot` of its --out folder (a path that cannot exist here, so it passes only on the
   folder the checker made), an inline `dvpr run ... && dvpr replay results/golden` (no --out:
   results/golden must not appear in the tree), a subcommand named inline, an existing script;
2. each planted fault is refused (exit 1) with the doc's file:line and dvpr's words: a config key
   that does not exist (on a continuation line, named at the command's first line), a config file
   that does not exist, a renamed flag, a renamed subcommand, a subcommand named inline that
   `dvpr --help` does not list, a script that does not exist, an inline override with an unknown
   key (run with the command above it), a value the doc sets that the shrink would have replaced
   (`runs=0` on a config the checker shrinks with runs=1), a plot of a folder no command writes,
   and a plot after the command that writes its folder failed;
3. exit 2 when a doc is missing.

Usage: tests/tools/test_doc_commands.py DVPR [REPO_ROOT]
"""
import pathlib
import subprocess
import sys
import tempfile

DVPR = str(pathlib.Path(sys.argv[1]).resolve())
SOURCE = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else pathlib.Path(__file__).resolve().parents[2])
GOLDEN = "tests/golden/golden.yaml"

GOOD = f"""# A doc

```
dvpr run {GOLDEN} --set runs=1 \\
  --out /nonexistent/doc_check_golden
dvpr plot /nonexistent/doc_check_golden
```

- `dvpr run {GOLDEN} && dvpr replay results/golden`: a page.
- `dvpr replay` draws it; `bash scripts/demo.sh --set runs=2` runs the demo.
"""


def run(doc):
    r = subprocess.run([sys.executable, str(SOURCE / "scripts/check_doc_commands.py"), "--dvpr", DVPR,
                        "--root", str(SOURCE), "--docs", str(doc)], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def refused(doc, text, wants, what):
    doc.write_text(text)
    code, out, err = run(doc)
    assert code == 1, f"{what}: exit {code}, expected 1\n{out}{err}"
    for want in wants:
        assert want.replace("DOC", str(doc)) in err, f"{what}: no '{want}' in\n{err}"


def fenced(*lines):
    return "# A doc\n\n```\n" + "\n".join(lines) + "\n```\n"


def main():
    golden_folder = SOURCE / "results/golden"
    existed = golden_folder.exists()
    with tempfile.TemporaryDirectory() as tmp:
        doc = pathlib.Path(tmp) / "fake.md"

        # 1. Right commands pass.
        doc.write_text(GOOD)
        code, out, err = run(doc)
        assert code == 0, f"the good doc: exit {code}\n{out}{err}"
        for want in (f"{doc}:4 ok", f"{doc}:6 ok", f"{doc}:9 ok", f"{doc}:10 ok", "check_doc_commands: all 6 commands"):
            assert want in out, f"the good doc: no '{want}' in\n{out}"
        assert existed or not golden_folder.exists(), "the checker wrote results/golden into the tree"

        # 2. Planted faults.
        refused(doc, fenced(f"dvpr run {GOLDEN} --out /tmp/g \\", "  --set dataset.no_such_key=1"),
                ["DOC:4: FAILED", "dataset.no_such_key: unknown key"], "a config key that does not exist")
        refused(doc, fenced("dvpr run experiments/configs/no_such.yaml --out /tmp/g"),
                ["DOC:4: FAILED", "experiments/configs/no_such.yaml: cannot read"], "a config file that does not exist")
        refused(doc, fenced(f"dvpr run {GOLDEN} --outdir /tmp/g"),
                ["DOC:4: FAILED", "unknown option --outdir"], "a renamed flag")
        refused(doc, fenced(f"dvpr simulate {GOLDEN}"), ["DOC:4: FAILED", "exit 2"], "a renamed subcommand")
        refused(doc, "Run `dvpr simulate` to see.\n",
                ["DOC:1: FAILED", "`dvpr --help` lists no subcommand `dvpr simulate`"], "a subcommand named inline")
        refused(doc, "Run `bash scripts/no_such.sh`.\n",
                ["DOC:1: FAILED", "scripts/no_such.sh: no such script"], "a script that does not exist")
        refused(doc, fenced(f"dvpr run {GOLDEN} --out /tmp/g") + "\nThen `--set verification.no_such=0`.\n",
                ["DOC:7: FAILED", "verification.no_such: unknown key"], "an inline override with an unknown key")
        refused(doc, fenced("dvpr run experiments/configs/replay_demo.yaml --set runs=0"),
                ["DOC:4: FAILED", "runs: must be in [1, 100000], got 0"], "a value the shrink would replace")
        refused(doc, fenced("dvpr plot /nonexistent/never_written"),
                ["DOC:4: FAILED", "/nonexistent/never_written: no earlier command in the docs writes it"],
                "a plot of a folder no command writes")
        refused(doc, fenced(f"dvpr run {GOLDEN} --set runs=0 --out /tmp/g", "dvpr plot /tmp/g"),
                ["DOC:5: FAILED", "not run: the command that writes its folder (DOC:4) failed"],
                "a plot after its folder's command failed")

        # 3. A missing doc.
        code, out, err = run(pathlib.Path(tmp) / "gone.md")
        assert code == 2 and "gone.md: no such file" in err, f"a missing doc: exit {code}\n{err}"
    print("check_doc_commands: the good doc passes; 10 broken commands are refused, a missing doc exits 2")


if __name__ == "__main__":
    main()
