#!/usr/bin/env python3
"""A catalogue of bad inputs a new user might give `dvpr run`, and what dvpr does with each.

    python3 tests/tools/bad_inputs.py BUILD/dvpr SCRATCH_DIR [--report] [--markdown]
            [--json FILE] [--before tests/tools/bad_inputs/before.json] [--only 'a*'] [--jobs N]
    python3 tests/tools/bad_inputs.py --list          (the cases, with why for debatable ones)

Each case is one bad input (a --set value, a config file, a data file, a flag, a result folder
that already exists), grouped by category (a: quantities, b: YAML structure, c: files, d: robots,
e: command line, f: result folders, g: later keys, h: checks before work, i: hostile input: names
and paths with shell syntax, planted links, foreign files, LCM URLs, output places; these also
run dvpr plot, replay, launch or agent; j: a team's own descriptor files). The harness runs dvpr on it in its own folder under
SCRATCH_DIR and records the exit code, the stderr lines, whether stderr names what the case says
it should (the key, file or flag), whether anything was left behind (a result folder, temporary
files), whether an earlier result folder was changed, and any sanitizer report or signal.

Each case is classified as one of
    clear error        exit 1 (2 for usage), one stderr line naming the key/file/flag, nothing
                       left behind, an earlier result folder byte-identical;
    crash              a signal, a sanitizer report, `terminate called`, an exit code above 2,
                       a timeout (60 s);
    silent acceptance  exit 0 although the input is bad;
    partial output     an error, but a result folder or temporary files were left, or an earlier
                       result folder was changed (or, for a run that should succeed, files of an
                       earlier run were left beside the new ones);
    misleading error   an error, but not one line, not naming what it should, naming something
                       it should not, or with the wrong exit code;
    ok                 (only the few cases that must succeed) it did, and left a whole folder.
It prints a table per category and the failing cases, and exits 1 if any case is neither a clear
error nor ok (--report: always 0, for a before/after table). The cases are in
bad_inputs/catalogue.py; docs/bad_inputs.md explains them. Run it on the sanitizer build: a
Release build turns some overflows into plausible-looking numbers. Python 3 standard library only.
"""

import argparse
import concurrent.futures
import dataclasses
import fnmatch
import hashlib
import json
import os
import re
import shutil
import stat
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Optional

HERE = Path(__file__).resolve().parent
CASES = HERE / "bad_inputs"
sys.path.insert(0, str(CASES))
from catalogue import KITTI, Case, catalogue, default_files, write  # noqa: E402

CLASSES = ["clear error", "crash", "silent acceptance", "misleading error", "partial output", "ok"]
PASSING = {"clear error", "ok"}
CATEGORIES = {
    "a": "quantities out of range",
    "b": "YAML structure",
    "c": "files",
    "d": "robots",
    "e": "command line",
    "f": "result folders",
    "g": "later keys (start_time, failover, BoW files)",
    "h": "checks before work",
    "i": "hostile input (names, links, foreign files, URLs, output places)",
    "j": "a team's own descriptor files (dataset.trajectories[i].descriptors)",
}
TIMEOUT_S = 60
SANITIZER = re.compile(
    r"ERROR: (Address|Leak|Memory|Thread)Sanitizer|runtime error:|UndefinedBehaviorSanitizer|"
    r"terminate called|Segmentation fault|stack-overflow|Assertion .* failed")
TEMPORARY = re.compile(r"(^\.|tmp|temp|~$|\.part$)", re.IGNORECASE)
# A line naming the result folder `out` (the cases' --out): a run may refuse an existing folder.
LOGS = ("stderr.txt", "stdout.txt")  # written by the harness for the interrupted case
NAMES_OUT = re.compile(r"(^|[\s'\"/])out([\s'\":/]|$)")


# ---------------------------------------------------------------------------------------------
# Running one case.

def snapshot(root):
    """relative path -> sha256 of each file ('/' for a folder) under root."""
    snap = {}
    for dirpath, dirnames, filenames in os.walk(root):
        rel = Path(dirpath).relative_to(root)
        for d in dirnames:
            snap[str(rel / d)] = "/"
        for name in filenames:
            p = Path(dirpath) / name
            try:
                # Only regular files are read: a case's FIFO would block the read for ever.
                if not stat.S_ISREG(os.stat(p).st_mode):
                    snap[str(rel / name)] = "special"
                    continue
                snap[str(rel / name)] = hashlib.sha256(p.read_bytes()).hexdigest()
            except OSError:
                snap[str(rel / name)] = "?"
    return snap


def outside_inputs(snap):
    return {k: v for k, v in snap.items() if k != "in" and not k.startswith("in/")}


def prepare_config(case, in_dir):
    text = (CASES / case.base).read_text()
    text = text.replace("data/kitti/00_poses.txt", str(KITTI))
    if case.edit:
        text = case.edit(text)
    config = in_dir / Path(case.base).name
    write(config, text)
    return config


def dvpr_argv(case, dvpr, config, case_dir):
    fill = lambda a: a.replace("{config}", str(config)).replace("{in}", str(case_dir / "in")) \
        .replace("{case}", str(case_dir))
    if case.argv is not None:
        args = [fill(a) for a in case.argv]
    else:
        args = ["run", str(config), "--quiet", "--out", "out"]
        for s in case.sets:
            args += ["--set", s]
    return [str(dvpr)] + args


def run_interrupted(argv, cwd, env, before):
    """Runs argv, sends SIGINT at the first change under cwd; returns (rc, err, fired)."""
    with open(cwd / "stderr.txt", "wb") as err, open(cwd / "stdout.txt", "wb") as out:
        proc = subprocess.Popen(argv, cwd=cwd, env=env, stdout=out, stderr=err)
        fired = False
        deadline = time.monotonic() + TIMEOUT_S
        while proc.poll() is None and time.monotonic() < deadline:
            now = outside_inputs(snapshot(cwd))
            if any(k not in before and k not in LOGS for k in now) or \
                    any(before.get(k) != now.get(k) for k in before):
                proc.send_signal(signal.SIGINT)
                fired = True
                break
            time.sleep(0.002)
        try:
            rc = proc.wait(timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            proc.kill()
            rc = proc.wait()
    return rc, (cwd / "stderr.txt").read_bytes(), fired


@dataclasses.dataclass
class Result:
    case: Case
    cls: str = ""
    rc: Optional[int] = None
    lines: list = dataclasses.field(default_factory=list)
    named: bool = False
    left: list = dataclasses.field(default_factory=list)
    prior_changed: list = dataclasses.field(default_factory=list)
    sanitizer: str = ""
    reasons: list = dataclasses.field(default_factory=list)
    seconds: float = 0.0
    out_dir: Optional[Path] = None
    new: list = dataclasses.field(default_factory=list)  # paths that were not there before


def contains(text, word):
    return any(w in text for w in word) if isinstance(word, tuple) else word in text


def prepare_case(case, scratch, priors):
    """The case's folder: inputs in in/, an earlier result folder at out/ if any, an empty
    tmpdir/ for dvpr's TMPDIR (files it leaves there count as left). Returns (folder, config)."""
    case_dir = scratch / case.id
    shutil.rmtree(case_dir, ignore_errors=True)
    in_dir = case_dir / "in"
    in_dir.mkdir(parents=True)
    default_files(in_dir)
    config = prepare_config(case, in_dir)
    if case.files:
        case.files(in_dir)
    if case.prior == "file":
        write(case_dir / "out", "an earlier file the user keeps\n")
    elif case.prior:
        shutil.copytree(priors[case.prior], case_dir / "out", symlinks=True)
    (case_dir / "tmpdir").mkdir()
    if case.setup:
        case.setup(case_dir)
    return case_dir, config


def run_case(case, dvpr, scratch, priors):
    case_dir, config = prepare_case(case, scratch, priors)
    env = dict(os.environ, TMPDIR=str(case_dir / "tmpdir"))
    before = outside_inputs(snapshot(case_dir))
    argv = dvpr_argv(case, dvpr, config, case_dir)
    start = time.monotonic()
    fired = True
    if case.interrupt:
        rc, err, fired = run_interrupted(argv, case_dir, env, before)
    else:
        try:
            p = subprocess.run(argv, cwd=case_dir, env=env, capture_output=True,
                               timeout=TIMEOUT_S)
            rc, err = p.returncode, p.stderr
        except subprocess.TimeoutExpired as e:
            rc, err = None, e.stderr or b""
    r = Result(case, rc=rc, seconds=time.monotonic() - start, out_dir=case_dir / "out")
    text = err.decode("utf-8", "replace")
    # Shown without the scratch path, so tables from two machines compare.
    r.lines = [line.replace(str(scratch) + "/", "") for line in text.splitlines() if line.strip()]
    m = SANITIZER.search(text)
    r.sanitizer = m.group(0) if m else ""
    r.named = all(contains(text, w) for w in case.expect)
    after = {k: v for k, v in outside_inputs(snapshot(case_dir)).items() if k not in LOGS}
    note_changes(r, before, after)
    classify(r, text, fired, after)
    return r


def note_changes(r, before, after):
    """Fills r.new, r.left and r.prior_changed from the case folder before and after the run."""
    r.new = sorted(k for k in after if k not in before)
    if not r.case.prior:
        r.left = sorted({k.split("/")[0] for k in r.new})
        return
    r.left = sorted(k for k in r.new if not k.startswith("out/") or TEMPORARY.search(Path(k).name))
    # Temporaries are reported as left, not again as changes.
    r.prior_changed = sorted(k for k in set(before) | set(after)
                             if k.startswith("out") and before.get(k) != after.get(k)
                             and not (k not in before and TEMPORARY.search(Path(k).name)))


def classify(r, text, fired, after):
    c = r.case
    if r.rc is None:
        r.cls, r.reasons = "crash", ["timeout after %d s" % TIMEOUT_S]
        return
    expected_signal = c.interrupt and r.rc in (-signal.SIGINT, 128 + signal.SIGINT)
    if r.sanitizer or (r.rc < 0 and not expected_signal) or (r.rc > 2 and not expected_signal):
        r.cls = "crash"
        r.reasons = ["sanitizer report (" + r.sanitizer + ")" if r.sanitizer else
                     "signal %d" % -r.rc if r.rc < 0 else "exit %d" % r.rc]
        if r.rc == 1:
            r.reasons.append("exit 1, the code of a user error")
        return
    if c.success:
        classify_success(r, after)
        return
    if c.interrupt:
        if not fired:
            r.reasons.append("the run ended before anything was written: not interrupted")
        r.reasons += changed_reasons(r)
        r.cls = "partial output" if r.left or r.prior_changed else \
            ("silent acceptance" if not fired else "clear error")
        return
    if r.rc == 0:
        r.cls, r.reasons = "silent acceptance", ["exit 0"]
        return
    r.reasons = changed_reasons(r) + message_problems(r, text)
    if r.left or r.prior_changed:
        r.cls = "partial output"
    elif r.reasons:
        r.cls = "misleading error"
    else:
        r.cls = "clear error"


def message_problems(r, text):
    """What is wrong with an error's exit code and stderr (empty: one clear line)."""
    c = r.case
    problems = []
    if r.rc != c.exit:
        problems.append("exit %d, expected %d" % (r.rc, c.exit))
    if len(r.lines) != 1:
        problems.append("%d stderr lines" % len(r.lines))
    missing = [w if isinstance(w, str) else "|".join(w) for w in c.expect if not contains(text, w)]
    # Refusing to replace an earlier folder is a documented choice of `dvpr run` (issue 12); other
    # commands on an earlier folder (replay, plot) must say what their case expects.
    reruns = c.argv is None or c.argv[0] == "run"
    if missing and reruns and c.prior and c.prior != "file" and len(r.lines) == 1 and \
            NAMES_OUT.search(r.lines[0]):
        missing = []
    if missing:
        problems.append("does not name " + ", ".join(missing))
    if any((ord(ch) < 32 and ch != "\t") or ch in "\x7f\ufffd" for line in r.lines
           for ch in line):
        problems.append("raw bytes in the message")
    bad = [w for w in c.forbid if w in text]
    if bad:
        problems.append("names " + ", ".join(bad) + " wrongly")
    return problems


def changed_reasons(r):
    out = []
    if r.left:
        out.append("left " + ", ".join(r.left[:4]) + (" ..." if len(r.left) > 4 else ""))
    if r.prior_changed:
        out.append("changed the earlier folder: " + ", ".join(r.prior_changed[:3]) +
                   (" ..." if len(r.prior_changed) > 3 else ""))
    return out


def classify_success(r, after):
    """A fine input: it must run and leave one whole folder (or refuse to replace, see f05)."""
    c = r.case
    if r.rc == 0:
        problems = []
        if not any(k == "out/runs.csv" or (k.startswith("out/") and k.endswith("/runs.csv")) for k in after):
            problems.append("no runs.csv")  # in out/, or in a folder inside it (--out out/NAME)
        if c.check:
            problems += c.check(r.out_dir)
        temps = [k for k in r.new if TEMPORARY.search(Path(k).name) or k.split("/")[0] != "out"]
        problems += ["left " + t for t in temps[:3]]
        r.reasons = problems
        r.cls = "partial output" if problems else "ok"
        return
    r.reasons = changed_reasons(r) + ["refused a valid input (exit %d)" % r.rc]
    refused = c.prior and not r.prior_changed and not r.left and len(r.lines) == 1 and \
        r.rc == 1 and NAMES_OUT.search(r.lines[0])
    if refused:
        r.cls, r.reasons = "ok", ["refused to replace the earlier folder"]
    else:
        r.cls = "partial output" if r.left or r.prior_changed else "misleading error"


# ---------------------------------------------------------------------------------------------
# Earlier result folders and the controls (the base configs must run cleanly).

def make_prior(key, dvpr, scratch):
    base = key.split("+")[0]
    d = scratch / "_prior" / key.replace("+", "_")
    shutil.rmtree(d, ignore_errors=True)
    in_dir = d / "in"
    in_dir.mkdir(parents=True)
    default_files(in_dir)
    config = prepare_config(Case("prior", "", base=base), in_dir)
    argv = [str(dvpr), "run", str(config), "--quiet", "--out", "out"]
    if key.endswith("+messages"):
        argv += ["--set", "outputs.messages=true"]
    p = subprocess.run(argv, cwd=d, capture_output=True, timeout=TIMEOUT_S)
    if p.returncode != 0 or not (d / "out" / "runs.csv").exists():
        sys.exit("bad_inputs.py: the control run of %s failed (exit %d), so no case would mean "
                 "anything:\n%s" % (key, p.returncode, p.stderr.decode("utf-8", "replace")))
    return d / "out"


# ---------------------------------------------------------------------------------------------
# Report.

def tables(results, markdown, before=None):
    """Counts per category and class; with `before` (id -> class) each cell is `before > now`."""
    out = []
    header = ["category", "cases"] + CLASSES

    def counts(rs):
        now = [sum(r.cls == c for r in rs) for c in CLASSES]
        if before is None:
            return [str(n) for n in now]
        was = [sum(before.get(r.case.id) == c for r in rs) for c in CLASSES]
        return ["%d > %d" % (w, n) if w != n else str(n) for w, n in zip(was, now)]

    rows = []
    for cat, title in CATEGORIES.items():
        rs = [r for r in results if r.case.category == cat]
        if rs:
            rows.append(["(%s) %s" % (cat, title), str(len(rs))] + counts(rs))
    rows.append(["all", str(len(results))] + counts(results))
    if markdown:
        out.append("| " + " | ".join(header) + " |")
        out.append("|" + "---|" * len(header))
        out += ["| " + " | ".join(row) + " |" for row in rows]
    else:
        widths = [max(len(row[i]) for row in rows + [header]) for i in range(len(header))]
        fmt = lambda row: "  ".join(v.ljust(widths[0]) if i == 0 else v.rjust(widths[i])
                                    for i, v in enumerate(row))
        out += [fmt(header)] + [fmt(row) for row in rows]
    return out


def first_line(r, width=110):
    line = r.lines[0] if r.lines else ""
    return line if len(line) <= width else line[:width - 3] + "..."


def case_lines(results, markdown, failing_only):
    out = []
    chosen = [r for r in results if r.cls not in PASSING] if failing_only else results
    if markdown:
        out.append("| case | bad input | class | exit | lines | names it | why / first stderr line |")
        out.append("|---|---|---|---|---|---|---|")
        for r in chosen:
            why = "; ".join(r.reasons) if r.cls not in PASSING else ""
            detail = (why + " - " if why else "") + "`" + first_line(r, 90).replace("|", "\\|") + "`"
            out.append("| %s | %s | %s | %s | %d | %s | %s |" % (
                r.case.id, r.case.what.replace("|", "\\|"), r.cls, r.rc, len(r.lines),
                "yes" if r.named else "no", detail if r.lines else why))
    else:
        for r in chosen:
            out.append("%s %-18s exit %-4s %d line(s)  %s" % (r.case.id, r.cls, r.rc, len(r.lines),
                                                               r.case.what))
            if r.reasons and r.cls not in PASSING:
                out.append("      " + "; ".join(r.reasons))
            if r.lines:
                out.append("      stderr: " + first_line(r))
    return out


def changes(results, before):
    out = []
    for r in results:
        was = before.get(r.case.id, "new case")
        if was != r.cls:
            out.append("%s %s > %s  %s" % (r.case.id, was, r.cls, r.case.what))
    return out or ["(none)"]


def as_json(r):
    return {"id": r.case.id, "category": r.case.category, "what": r.case.what, "class": r.cls,
            "exit": r.rc, "stderr_lines": len(r.lines), "stderr_first": r.lines[:3],
            "names_expected": r.named, "expected": [list(w) if isinstance(w, tuple) else w
                                                    for w in r.case.expect],
            "left": r.left, "earlier_folder_changed": r.prior_changed,
            "sanitizer": r.sanitizer, "reasons": r.reasons, "seconds": round(r.seconds, 2),
            "why": r.case.why}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dvpr", type=Path, nargs="?", help="the dvpr binary")
    ap.add_argument("scratch", type=Path, nargs="?", help="a scratch folder (emptied case by case)")
    ap.add_argument("--report", action="store_true", help="always exit 0 (before/after tables)")
    ap.add_argument("--markdown", action="store_true", help="tables in Markdown, every case")
    ap.add_argument("--json", type=Path, help="write every case's record to this file")
    ap.add_argument("--before", type=Path,
                    help="an earlier --json file: show `before > now` counts and what changed")
    ap.add_argument("--only", default="*", help="run the cases whose id matches (glob: 'a*')")
    ap.add_argument("--jobs", type=int, default=1, help="cases run at once (default 1)")
    ap.add_argument("--list", action="store_true", help="list the cases and exit")
    args = ap.parse_args()
    cases = [c for c in catalogue() if fnmatch.fnmatch(c.id, args.only)]
    if args.list:
        for c in cases:
            print("%s  %s%s" % (c.id, c.what, ("\n      why: " + c.why) if c.why else ""))
        return 0
    if args.scratch is None:
        ap.error("needs the dvpr binary and a scratch folder")
    if not os.access(args.dvpr, os.X_OK):
        print("bad_inputs.py: %s is not an executable" % args.dvpr, file=sys.stderr)
        return 2
    dvpr = args.dvpr.resolve()
    scratch = args.scratch.resolve()
    scratch.mkdir(parents=True, exist_ok=True)
    priors = {key: make_prior(key, dvpr, scratch)
              for key in sorted({c.prior for c in cases if c.prior and c.prior != "file"} |
                                {"base.yaml", "files.yaml", "centroids.yaml"})}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(lambda c: run_case(c, dvpr, scratch, priors), cases))
    before = None
    if args.before:
        before = {r["id"]: r["class"] for r in json.loads(args.before.read_text())}
    lines = tables(results, args.markdown, before)
    if before is not None:
        lines += ["", "changed since %s:" % args.before] + changes(results, before)
    failing = [r for r in results if r.cls not in PASSING]
    lines += ["", "every case:" if args.markdown else "failing cases (%d):" % len(failing)]
    lines += case_lines(results, args.markdown, failing_only=not args.markdown)
    print("\n".join(lines))
    if args.json:
        args.json.write_text(json.dumps([as_json(r) for r in results], indent=1) + "\n")
    return 0 if args.report or not failing else 1


if __name__ == "__main__":
    sys.exit(main())
