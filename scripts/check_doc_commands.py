#!/usr/bin/env python3
"""Runs every dvpr command that README.md and docs/teaching.md show, so that a renamed config key,
config file, subcommand or flag fails CI instead of the reader who copies the command.

What a command is (read from the markdown, in order):
- in a fenced code block, a line that begins with `dvpr ` or `bash scripts/` (after an optional
  `$ `), joined with the lines its trailing backslashes continue;
- outside them, an inline code span that begins so (README's examples are written that way);
  `a && b` is two commands;
- an inline span `dvpr <word>` alone (`dvpr launch`) names a subcommand: `dvpr --help` must list
  it; `dvpr` alone is the program's name;
- an inline span that begins with `--set ` is an override the text applies to the command above
  it (teaching.md: "set `--set verification.request_bytes=0` and compare"): that command runs
  again with it.
`bash scripts/X.sh ...` is only checked to name an existing script (the demo builds for minutes;
the tests run the suite this check is part of).

How a command runs: with --dvpr for `dvpr`, from the repository's root, as the doc writes it,
except that
- `--out X` becomes a fresh temporary folder, and `dvpr run` without --out gets one too (it would
  write results/<config name> into the tree);
- a later command that names X (`dvpr plot /tmp/lesson`, `dvpr replay results/replay_demo`) gets
  that folder, so it runs on what the earlier command wrote; a `results/<name>` that no earlier
  command writes (README's `dvpr plot results/paper_kitti00`, the demo's folder) is first made by
  `dvpr run experiments/configs/<name>.yaml`, shrunk as below;
- a `dvpr run` of a config in SHRINK gets that config's overrides, each only where the command
  sets no value for the key itself (nor for a map above it or a key below it): every key and
  value the doc writes is read as written, and what is added only makes the sweep smaller (one
  run, fewer frames, fewer team sizes, 2000 training samples for k-means instead of 20000). Every
  key of the config file is read too (dvpr refuses an unknown one before any run); the file's own
  values of the shrunk keys are replaced here, and read as they are by
  SweepSizeTest.EveryShippedConfigPassesWithoutTheFlag.
`dvpr launch` and `dvpr agent` need multicast and real time: a doc that shows one fails here until
this script is taught where it writes.

Usage: scripts/check_doc_commands.py --dvpr PATH [--root REPO_ROOT] [--docs FILE ...]
       scripts/check_doc_commands.py --dvpr PATH --self-test   (tests/tools/test_doc_commands.py)
Prints one line per command (file:line, ok or FAILED, seconds, the command as written).
exit 0: every command ran, 1: one failed (its file:line, what ran and its stderr on stderr),
2: a doc cannot be read
"""
import argparse
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile
import time

DOCS = ("README.md", "docs/teaching.md")
TIMEOUT_S = 300
# Overrides that keep a config's doc commands cheap, added only for keys a command does not set.
# Seconds are wall time on 2 cores with the sanitizer build (build/asan), as written -> shrunk:
#   bandwidth_scaling: teaching lesson 1 (frames 1500, runs 1) 28.7 s -> 4.1 s (and 3.5 s for each
#     of its two inline overrides), lesson 2 (5 shared-medium bandwidths, all frames) 27.9 s ->
#     1.7 s, README's plain command (6 team sizes x 3 runs x 6 networks, all frames) about ten
#     times lesson 1 -> 1.7 s
#   radio_kitti00: lesson 4 (n = 20, six networks, all frames) 16.7 s -> 2.7 s; README's plain
#     command (3 team sizes x 3 runs x 11 networks) several minutes -> 2.4 s
#   contention, paper_kitti00 (README, and the folder of `dvpr plot results/paper_kitti00`):
#     minutes (7 and 19 team sizes, 3 and 10 runs, all frames) -> 1.7 and 1.9 s
#   staggered_kitti00: 104 s with runs=1 alone -> 2.3 s; strategies: 52 s with runs=1, frames=300
#     and robots=[2,5] (3.6 minutes in Release as written) -> 4.6 s
#   replay_demo: 4.1 s, of which 3.3 s is k-means on 20000 training samples -> 1.1 s
# Not here, so run as written: tests/golden/golden.yaml (1.6 s). The whole check: about 36 s.
SMALL = {"runs": "1", "dataset.frames": "300", "training.synthetic.samples": "2000"}
SHRINK = {
    "experiments/configs/bandwidth_scaling.yaml": {**SMALL, "robots": "[2,4]"},
    "experiments/configs/radio_kitti00.yaml": {**SMALL, "robots": "[5]"},
    "experiments/configs/contention.yaml": {**SMALL, "robots": "[2,4]"},
    "experiments/configs/paper_kitti00.yaml": {**SMALL, "robots": "[2,3]"},
    "experiments/configs/staggered_kitti00.yaml": SMALL,
    "experiments/configs/strategies.yaml": {**SMALL, "robots": "[2,5]"},
    "experiments/configs/replay_demo.yaml": SMALL,
}
VALUE_FLAGS = {"--out", "--set", "--threads", "--robots", "--run", "--network", "--strategy"}
SHELL_OPERATORS = {"|", "||", ";", ">", ">>", "<", "&", "(", ")"}
FENCE = re.compile(r"^\s*(```|~~~)")
SPAN = re.compile(r"`([^`]+)`")
COMMAND_START = re.compile(r"^(dvpr(\s|$)|bash\s+scripts/)")
CONFIG_NAME = re.compile(r"^name:\s*[\"']?([^\"'\s#]+)", re.M)


class CannotRead(Exception):
    pass


class Step:
    """One line of the report: a command to run (argv), or a check already decided (problem:
    refused, else passed). `after`: the step whose output folder this one reads; `listed`: a
    subcommand `dvpr --help` (argv) must list."""

    def __init__(self, where, text, argv=None, problem=None, after=None, listed=None):
        self.where, self.text, self.argv, self.problem, self.after, self.listed = where, text, argv, problem, after, listed
        self.ok, self.seconds, self.stderr, self.code = None, 0.0, "", None


# ---------------------------------------------------------------- the docs' commands

def doc_commands(path):
    """(line, text) of each command of a markdown file, in order (see the module's docstring)."""
    lines = path.read_text().splitlines()
    found, outside, fenced, i = [], [], False, 0
    while i < len(lines):
        line = lines[i]
        if FENCE.match(line):
            fenced = not fenced
            outside.append("")
        elif fenced:
            text, start = re.sub(r"^\s*\$\s+", "", line).strip(), i
            while text.endswith("\\") and i + 1 < len(lines):
                i += 1
                text = text[:-1].rstrip() + " " + lines[i].strip()
                outside.append("")
            if COMMAND_START.match(text):
                found.append((start + 1, text))
            outside.append("")
        else:
            outside.append(line)
        i += 1
    prose = "\n".join(outside)
    for m in SPAN.finditer(prose):
        text = " ".join(m.group(1).split())
        if COMMAND_START.match(text) or text.startswith("--set "):
            found.append((prose.count("\n", 0, m.start()) + 1, text))
    return sorted(found, key=lambda item: item[0])


def words(text):
    lexer = shlex.shlex(text, posix=True, punctuation_chars=True)
    lexer.whitespace_split = True
    return list(lexer)


def split_and(argv):
    parts, part = [], []
    for w in argv:
        if w == "&&":
            parts.append(part)
            part = []
        else:
            part.append(w)
    return parts + [part]


def positionals(argv, start):
    """The arguments from argv[start] on that are neither flags nor a flag's value."""
    found, i = [], start
    while i < len(argv):
        if argv[i] in VALUE_FLAGS:
            i += 2
            continue
        if not argv[i].startswith("-"):
            found.append((i, argv[i]))
        i += 1
    return found


def set_values(argv):
    """key -> value of each `--set key=value` of a command."""
    return dict(argv[i + 1].split("=", 1) for i in range(len(argv) - 1)
                if argv[i] == "--set" and "=" in argv[i + 1])


# ---------------------------------------------------------------- from a command to what runs

class Planner:
    """Turns the docs' commands into steps: rewritten output folders, the folders later commands
    name, shrink overrides."""

    def __init__(self, root, dvpr, tmp):
        self.root, self.dvpr, self.tmp = root, dvpr, tmp
        self.steps, self.folders, self.count, self.last_run = [], {}, 0, None

    def fresh(self, name="out"):
        self.count += 1
        folder = self.tmp / f"{self.count:02d}"
        folder.mkdir()
        return str(folder / name)

    def add(self, step):
        self.steps.append(step)
        return len(self.steps) - 1

    def item(self, where, text):
        if text.startswith("--set "):
            return self.fragment(where, text)
        argv = words(text)
        bad = sorted(set(argv) & SHELL_OPERATORS)
        if bad:
            return self.add(Step(where, text, problem=f"'{' '.join(bad)}' in a command: this script runs "
                                                       f"`a && b` only; teach it the rest"))
        parts = split_and(argv)
        for part in parts:
            self.part(where, shlex.join(part) if len(parts) > 1 else text, part)

    def part(self, where, text, argv):
        if argv[:1] == ["bash"]:
            script = argv[1] if len(argv) > 1 else ""
            if (self.root / script).is_file():
                return self.add(Step(where, f"{text}   (the script exists; not run)"))
            return self.add(Step(where, text, problem=f"{script}: no such script in the repository"))
        if argv[:1] != ["dvpr"]:
            return self.add(Step(where, text, problem="after && comes no dvpr or bash scripts/ command"))
        if len(argv) == 1:
            return None
        if len(argv) == 2 and not argv[1].startswith("-"):
            return self.add(Step(where, text, argv=[self.dvpr, "--help"], listed=f"dvpr {argv[1]}"))
        sub = argv[1]
        if sub == "run":
            self.last_run = argv
            return self.run(where, text, argv, keep=True)
        if sub in ("plot", "replay"):
            return self.reader(where, text, argv)
        if sub in ("launch", "agent"):
            return self.add(Step(where, text, problem=f"this script does not run `dvpr {sub}` (multicast, "
                                                       f"real time, its own output): teach it"))
        return self.add(Step(where, text, argv=[self.dvpr] + argv[1:]))

    def run(self, where, text, argv, keep):
        """A `dvpr run`: --out rewritten or added, the config's shrink for keys the command leaves
        alone. keep: later commands may name its folder."""
        argv, sets = list(argv), set_values(argv)
        config = next((a for _, a in positionals(argv, 2)), "")
        out = self.fresh()
        if "--out" in argv[:-1]:
            i = argv.index("--out")
            written, argv[i + 1] = argv[i + 1], out
        else:
            written = f"results/{sets.get('name') or self.config_name(config)}"
            argv += ["--out", out]
        for key, value in SHRINK.get(os.path.normpath(config), {}).items():
            if not any(key == s or key.startswith(s + ".") or s.startswith(key + ".") for s in sets):
                argv += ["--set", f"{key}={value}"]
        index = self.add(Step(where, text, argv=[self.dvpr] + argv[1:]))
        if keep:
            self.folders[os.path.normpath(written)] = (out, index)
        return index

    def config_name(self, config):
        try:
            m = CONFIG_NAME.search((self.root / config).read_text())
        except OSError:
            return None  # dvpr says the config is missing
        return m.group(1) if m else None

    def reader(self, where, text, argv):
        """`dvpr plot DIR`, `dvpr replay DIR [--out FILE]`: DIR as an earlier command wrote it."""
        argv = list(argv)
        named = positionals(argv, 2)
        if not named:
            return self.add(Step(where, text, argv=[self.dvpr] + argv[1:]))
        i, folder = named[0]
        key = os.path.normpath(folder)
        if key not in self.folders:
            made = self.producer(where, key)
            if made is None:
                return self.add(Step(where, text, problem=f"{folder}: no earlier command in the docs writes it "
                                                           f"(and it is not results/<a config of experiments/configs>)"))
        argv[i], after = self.folders[key]
        if "--out" in argv[:-1]:
            j = argv.index("--out")
            argv[j + 1] = self.fresh(pathlib.Path(argv[j + 1]).name or "out")
        return self.add(Step(where, text, argv=[self.dvpr] + argv[1:], after=after))

    def producer(self, where, folder):
        m = re.fullmatch(r"results/([^/]+)", folder)
        config = f"experiments/configs/{m.group(1)}.yaml" if m else None
        if config is None or not (self.root / config).is_file():
            return None
        argv = ["dvpr", "run", config]
        return self.run(where, f"dvpr run {config}   (makes {folder}, which the next command reads)", argv, keep=True)

    def fragment(self, where, text):
        if self.last_run is None:
            return self.add(Step(where, text, problem="an override with no dvpr run command above it"))
        return self.run(where, f"{text}   (added to the dvpr run above)", self.last_run + words(text), keep=False)


# ---------------------------------------------------------------- running and reporting

def execute(step, steps, root):
    if step.problem is not None or step.argv is None:
        step.ok = step.problem is None
        return
    if step.after is not None and not steps[step.after].ok:
        step.ok, step.problem = False, f"not run: the command that writes its folder ({steps[step.after].where}) failed"
        return
    start = time.monotonic()
    try:
        r = subprocess.run(step.argv, cwd=root, capture_output=True, text=True, timeout=TIMEOUT_S)
        step.code, step.stderr, step.ok = r.returncode, r.stderr, r.returncode == 0
        if step.ok and step.listed and not re.search(rf"^\s*{re.escape(step.listed)}\b", r.stdout, re.M):
            step.ok, step.problem = False, f"`dvpr --help` lists no subcommand `{step.listed}`"
    except subprocess.TimeoutExpired:
        step.ok, step.problem = False, f"still running after {TIMEOUT_S} s"
    step.seconds = time.monotonic() - start


def print_line(step):
    print(f"{step.where} {'ok' if step.ok else 'FAILED'} {step.seconds:.1f}s {step.text}", flush=True)


def report(steps):
    failed = [s for s in steps if not s.ok]
    for s in failed:
        print(f"\n{s.where}: FAILED: {s.text}", file=sys.stderr)
        if s.problem:
            print(f"  {s.problem}", file=sys.stderr)
        if s.argv is not None and s.code is not None:
            print(f"  ran: {shlex.join(s.argv)}\n  exit {s.code}, stderr:\n{s.stderr.rstrip()}", file=sys.stderr)
    total = sum(s.seconds for s in steps)
    if failed:
        print(f"check_doc_commands: {len(failed)} of {len(steps)} commands failed ({total:.1f} s)", file=sys.stderr)
        return 1
    print(f"check_doc_commands: all {len(steps)} commands of the docs ran ({total:.1f} s)")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dvpr", required=True, help="the dvpr program to run the commands with")
    ap.add_argument("--root", default=str(pathlib.Path(__file__).resolve().parent.parent))
    ap.add_argument("--docs", nargs="+", default=list(DOCS), help="markdown files (relative: to --root)")
    ap.add_argument("--self-test", action="store_true", help="run tests/tools/test_doc_commands.py")
    args = ap.parse_args()
    root, dvpr = pathlib.Path(args.root).resolve(), str(pathlib.Path(args.dvpr).resolve())
    if args.self_test:
        test = root / "tests/tools/test_doc_commands.py"
        return subprocess.run([sys.executable, str(test), dvpr, str(root)]).returncode
    with tempfile.TemporaryDirectory(prefix="dvpr_doc_commands_") as tmp:
        planner = Planner(root, dvpr, pathlib.Path(tmp))
        try:
            for doc in args.docs:
                path = root / doc
                if not path.is_file():
                    raise CannotRead(f"{doc}: no such file")
                planner.last_run = None
                name = os.path.relpath(path, root) if path.resolve().is_relative_to(root) else doc
                for line, text in doc_commands(path):
                    planner.item(f"{name}:{line}", text)
        except (CannotRead, OSError, ValueError) as e:
            print(f"check_doc_commands: {e}", file=sys.stderr)
            return 2
        for step in planner.steps:
            execute(step, planner.steps, root)
            print_line(step)
        return report(planner.steps)


if __name__ == "__main__":
    sys.exit(main())
