#!/usr/bin/env python3
"""scripts/check_doc_numbers.py refuses a README whose quoted results disagree with their sources.

Copies the checker, README.md, docs/strategies.md and the golden runs.csv into a scratch tree,
checks that the copy passes, then changes one thing at a time and checks the verdict:
1. README's golden paper AUC 0.632 -> 0.633: exit 1 naming README.md's line;
2. the golden runs.csv's sim decentralized n = 5 AUC moved by 0.001: exit 1;
3. docs/strategies.md's static worst balance of the n = 20 row 1.32 -> 1.42: exit 1;
4. README's golden sentence reworded: exit 2 (the checker must be taught the new words).
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
FILES = ["scripts/check_doc_numbers.py", "README.md", "docs/strategies.md", "tests/golden/expected/runs.csv"]


def run(root):
    p = subprocess.run([sys.executable, str(root / FILES[0]), str(root)], capture_output=True, text=True)
    return p.returncode, p.stderr


def replace_once(path, old, new):
    text = path.read_text()
    if text.count(old) < 1:
        raise SystemExit(f"test_doc_numbers: '{old}' not in {path}: update this test")
    path.write_text(text.replace(old, new, 1))


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        scratch = pathlib.Path(tmp)

        def fresh():
            for f in FILES:
                (scratch / f).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy(SOURCE / f, scratch / f)

        def expect(label, want_rc, want_text):
            rc, err = run(scratch)
            if rc != want_rc or want_text not in err:
                failures.append(f"{label}: exit {rc}, expected {want_rc} with '{want_text}'; stderr: {err.strip()}")

        fresh()
        expect("the copy as it is", 0, "")
        replace_once(scratch / "README.md", "AUC 0.632 (paper protocol", "AUC 0.633 (paper protocol")
        expect("README's golden paper AUC changed", 1, "the README says 0.633, its source 0.632")
        fresh()
        runs = scratch / "tests/golden/expected/runs.csv"
        lines = runs.read_text().splitlines(keepends=True)
        header = lines[0].rstrip("\n").split(",")
        for i, line in enumerate(lines[1:], start=1):
            cells = line.rstrip("\n").split(",")
            if cells[0] == "sim" and cells[1] == "decentralized" and cells[2] == "5":
                cells[header.index("auc")] = str(float(cells[header.index("auc")]) + 0.001)
                lines[i] = ",".join(cells) + "\n"
                break
        runs.write_text("".join(lines))
        expect("the golden sim AUC moved", 1, "golden sim decentralized n = 5 AUC")
        fresh()
        replace_once(scratch / "docs/strategies.md", "| balanced_sample_c2+replicate_1_r8 | 20 | 0.985 | 1.32",
                     "| balanced_sample_c2+replicate_1_r8 | 20 | 0.985 | 1.42")
        expect("the measured table's worst balance changed", 1, "the README says 1.32, its source 1.42")
        fresh()
        replace_once(scratch / "README.md", "(paper protocol,", "(the paper's protocol,")
        expect("the golden sentence reworded", 2, "cannot find")
    for f in failures:
        print("FAILED " + f, file=sys.stderr)
    if not failures:
        print("test_doc_numbers: 5 cases as expected")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
