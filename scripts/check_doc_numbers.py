#!/usr/bin/env python3
"""Checks the result numbers README.md quotes against where they come from, so that a change to
the code or to a measured table that moves a number fails CI instead of leaving the README wrong.

- The golden run (`dvpr run tests/golden/golden.yaml`): "AUC A (paper protocol, decentralized,
  n = 3) and B (simulation, decentralized, n = 5; broadcast C)" against
  tests/golden/expected/runs.csv (what GoldenTest holds the sanitizer build to), each rounded to
  the 3 decimals the README writes.
- strategies.yaml at n = 20: "keeps the busiest robot at Wx its share (paper method: Px) with
  relative AUC R for Bx the paper method's bytes per query" against docs/strategies.md's measured
  table (static worst balance, the paper method's, static relative AUC, bytes vs paper), as
  rounded there and in the README.

Usage: scripts/check_doc_numbers.py [REPO_ROOT]
exit 0: every number agrees; 1: one does not (the README line, the number and its source's);
2: a claim or its source cannot be found (a reworded sentence must be taught here).
"""
import csv
import pathlib
import re
import sys


class Missing(Exception):
    pass


def find(pattern, text, what):
    m = re.search(pattern, text, re.S)
    if m is None:
        raise Missing(what)
    return m


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def golden_rows(root):
    with open(root / "tests/golden/expected/runs.csv", newline="") as f:
        return list(csv.DictReader(f))


def golden_auc(rows, protocol, strategy, robots):
    for r in rows:
        if r["protocol"] == protocol and r["strategy"] == strategy and r["robots"] == str(robots):
            return float(r["auc"])
    raise Missing(f"tests/golden/expected/runs.csv: no row {protocol} {strategy} n = {robots}")


def strategies_row(root, strategy, robots):
    """The cells of docs/strategies.md's table row for (strategy, n)."""
    for line in (root / "docs/strategies.md").read_text().splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 8 and cells[0] == strategy and cells[1] == str(robots):
            return cells
    raise Missing(f"docs/strategies.md: no table row for {strategy} at n = {robots}")


def check(root):
    """A list of (README line, what, quoted, source's) that disagree."""
    readme = (root / "README.md").read_text()
    wrong = []

    def agree(m, group, quoted_value, source_value, what):
        if quoted_value != source_value:
            wrong.append((line_of(readme, m.start(group)), what, quoted_value, source_value))

    m = find(r"AUC (\d\.\d+) \(paper protocol,\s+decentralized, n = 3\) and (\d\.\d+) \(simulation, "
             r"decentralized, n = 5; broadcast (\d\.\d+)\)", readme, "README.md: the golden run's AUCs")
    rows = golden_rows(root)
    for group, (protocol, strategy, robots) in enumerate(
            [("paper", "decentralized", 3), ("sim", "decentralized", 5), ("sim", "broadcast", 5)], start=1):
        quoted = m.group(group)
        source = f"{golden_auc(rows, protocol, strategy, robots):.{len(quoted.split('.')[1])}f}"
        agree(m, group, quoted, source, f"golden {protocol} {strategy} n = {robots} AUC (runs.csv)")

    m = find(r"At n = 20, `([^`]+)` keeps the busiest robot at\s+(\d+\.\d+)x its share \(paper method: "
             r"(\d+\.\d+)x\) with relative AUC (\d\.\d+) for (\d+\.\d+)x the paper method's bytes",
             readme, "README.md: strategies.yaml's n = 20 sentence")
    best = strategies_row(root, m.group(1), 20)
    paper = strategies_row(root, "decentralized", 20)

    def first_number(cell):
        return find(r"\d+(?:\.\d+)?", cell, f"a number in '{cell}'").group(0)

    def rounded(value, like):
        return f"{float(value):.{len(like.split('.')[1])}f}"

    agree(m, 2, m.group(2), rounded(first_number(best[3]), m.group(2)), "static worst balance (docs/strategies.md)")
    agree(m, 3, m.group(3), rounded(first_number(paper[3]), m.group(3)), "paper method's worst balance")
    agree(m, 4, m.group(4), rounded(best[2], m.group(4)), "static relative AUC")
    agree(m, 5, m.group(5), rounded(first_number(best[7]), m.group(5)), "bytes vs the paper method")
    return wrong


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[1])
    try:
        wrong = check(root)
    except (Missing, OSError) as e:
        print(f"check_doc_numbers: cannot find {e}", file=sys.stderr)
        return 2
    for line, what, quoted, source in wrong:
        print(f"README.md:{line}: {what}: the README says {quoted}, its source {source}", file=sys.stderr)
    if not wrong:
        print("check_doc_numbers: README.md's quoted results agree with their sources")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
