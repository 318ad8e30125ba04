"""The catalogue of bad inputs run by tests/tools/bad_inputs.py (see docs/bad_inputs.md).

Each Case is one bad input a new user might give `dvpr run`, on one of the small configs beside
this file (base.yaml, files.yaml, centroids.yaml, yaml/*.yaml), with what stderr must name. The
input files (poses, descriptors, centroids) are written by the functions below, deterministically.
Cases whose right behaviour is debatable say what they expect and why (`why`).
"""

import csv
import dataclasses
import os
import random
import re
import struct
import subprocess
import sys
from pathlib import Path
from typing import Callable, Optional

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent.parent
KITTI = REPO / "data" / "kitti" / "00_poses.txt"

# ---------------------------------------------------------------------------------------------
# Input files the cases write (deterministic; numbers from a seeded random.Random).

def kitti_lines(n):
    with open(KITTI) as f:
        lines = [next(f) for _ in range(n)]
    return "".join(lines)


def matrix(rows, cols, seed=1):
    rng = random.Random(seed)
    return [[rng.uniform(-1.0, 1.0) for _ in range(cols)] for _ in range(rows)]


def npy_bytes(m, descr="<f4", shape=None, fortran=False):
    """A version-1 .npy file of the 2-D list m (row-major data unless fortran)."""
    shape = shape if shape is not None else (len(m), len(m[0]) if m else 0)
    header = "{'descr': '%s', 'fortran_order': %s, 'shape': %s, }" % (
        descr, "True" if fortran else "False", "(" + ", ".join(str(s) for s in shape) +
        ("," if len(shape) == 1 else "") + ")")
    pad = 64 - (10 + len(header) + 1) % 64
    header += " " * (pad % 64) + "\n"
    flat = [v for row in (zip(*m) if fortran else m) for v in row]
    fmt = {"<f4": "f", "<f8": "d", "<i4": "i", ">f4": "f"}[descr]
    order = ">" if descr.startswith(">") else "<"
    values = [int(v) for v in flat] if fmt == "i" else flat
    data = struct.pack(order + fmt * len(values), *values)
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + data


def npy_with_header(header, m):
    """A .npy file with this header text (padded) and float32 rows m."""
    header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
    data = struct.pack("<%df" % (len(m) * len(m[0])), *[v for row in m for v in row])
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + data


def write(path, content):
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(content, str):
        content = content.encode()
    path.write_bytes(content)


def default_files(d):
    """The inputs of files.yaml and centroids.yaml (each case overwrites one)."""
    write(d / "poses.txt", kitti_lines(200))
    write(d / "desc.npy", npy_bytes(matrix(200, 32)))
    write(d / "c_n2_r0.npy", npy_bytes(matrix(2, 32, seed=2)))
    write(d / "c_n3_r0.npy", npy_bytes(matrix(3, 32, seed=3)))


def poses_with(n, line_no, replace):
    """n KITTI poses with line `line_no` (1-based) passed through replace(list of 12 tokens)."""
    lines = kitti_lines(n).splitlines()
    tokens = lines[line_no - 1].split()
    lines[line_no - 1] = " ".join(replace(tokens))
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# The catalogue.

@dataclasses.dataclass
class Case:
    id: str
    what: str                      # the bad input, as a user would describe it
    expect: tuple = ()             # stderr must contain each; a tuple entry: any one of them
    base: str = "base.yaml"        # config under bad_inputs/ the case starts from
    sets: tuple = ()               # --set arguments
    argv: Optional[list] = None    # dvpr arguments instead of `run CONFIG --quiet --out out SETS`
    exit: int = 1                  # expected exit code of the error
    forbid: tuple = ()             # stderr must not contain these (a mislabelled error)
    files: Optional[Callable] = None  # files(in_dir): writes/spoils the case's input files
    edit: Optional[Callable] = None   # edit(config_text) -> config_text
    prior: Optional[str] = None    # an earlier result folder at `out` (run of this base config)
    success: bool = False          # the input is fine: it must run and leave a whole folder
    check: Optional[Callable] = None  # check(out_dir) -> problems, for success cases
    interrupt: bool = False        # SIGINT at the run's first write
    setup: Optional[Callable] = None  # setup(case_dir): after the inputs and the earlier folder
    why: str = ""                  # why the expectation (debatable cases say so)

    @property
    def category(self):
        return self.id[0]


def S(*sets):
    return tuple(sets)


def spoil(name, content):
    return lambda d: write(d / name, content)


def set_key(key, value):
    """Edits one `key: value` line of a config (first occurrence)."""
    def edit(text):
        out, n = re.subn(r"(?m)^(\s*)" + re.escape(key) + r":.*$",
                         lambda m: m.group(1) + key + ": " + value, text, count=1)
        if n != 1:
            raise RuntimeError("no key " + key + " in the config")
        return out
    return edit


NAN_ROW = [float("nan")] + [0.5] * 31


def quantities():
    big = "999999999999999999999999999999"  # 30 digits: the most the quantity parser reads
    return [
        Case("a01", "network.latency with 30 digits of hours", ("network.latency",),
             sets=S("network.latency=" + big + "h")),
        Case("a02", "service.fixed = 2562047h (fits int64 ns, overflows virtual time)",
             ("service.fixed",), sets=S("service.fixed=2562047h")),
        Case("a03", "network.latency = 2562047h", ("network.latency",),
             sets=S("network.latency=2562047h")),
        Case("a04", "network.latency list with one overflowing value", ("network.latency",),
             sets=S("network.latency=[2ms, 2562047h]")),
        Case("a05", "service.per_comparison = 2562047h", ("service.per_comparison",),
             sets=S("service.per_comparison=2562047h")),
        Case("a06", "dataset.fps = 1e-9 (frame k at k x 10^9 s)", ("dataset.fps",),
             sets=S("dataset.fps=1e-9")),
        Case("a07", "dataset.fps = 1e-300", ("dataset.fps",), sets=S("dataset.fps=1e-300")),
        Case("a08", "dataset.fps = 1e300 (every frame at t = 0)", ("dataset.fps",),
             sets=S("dataset.fps=1e300")),
        Case("a09", "verification.request_bytes = 3000000000 (beyond int32)",
             ("verification.request_bytes",), sets=S("verification.request_bytes=3000000000")),
        Case("a10", "verification.request_bytes = 4294992296 (2^32 + 25000)",
             ("verification.request_bytes",), sets=S("verification.request_bytes=4294992296")),
        Case("a11", "verification.request_bytes = 2^40, the allowed maximum",
             ("verification.request_bytes",), sets=S("verification.request_bytes=1099511627776"),
             why="2^40 bytes (1.1 TB) per request is not a geometric verification; if a range "
                 "keeps it, the run must send 2^40-byte requests, not 0-byte ones"),
        Case("a12", "verification.request_bytes with 30 digits of GB",
             ("verification.request_bytes",), sets=S("verification.request_bytes=" + big + "GB")),
        Case("a13", "network.bandwidth with 30 digits of Tbps", ("network.bandwidth",),
             sets=S("network.bandwidth=" + big + "Tbps")),
        Case("a14", "1 bit/s link and 2^40-byte requests (transmission beyond 292 years)",
             (("network.bandwidth", "verification.request_bytes"),),
             sets=S("network.bandwidth=1bps", "verification.request_bytes=1099511627776"),
             why="a request's transmission time at the configured bandwidth must be "
                 "representable (issue 12); 2^40 is the largest request_bytes accepted today"),
        Case("a15", "link override latency = 2562047h", ("network.links",),
             sets=S("network.links=[{src: 0, dst: 1, latency: 2562047h}]")),
        Case("a16", "dataset.synthetic.noise = 1e30 (squared distances overflow float)",
             ("dataset.synthetic.noise",), sets=S("dataset.synthetic.noise=1e30"),
             why="debatable: the knob has no documented upper bound; issue 12 asks for ranges "
                 "that keep every derived quantity (here squared descriptor distances) finite"),
        Case("a17", "evaluation.gt_radius_m = 1e200 (its square is inf)",
             ("evaluation.gt_radius_m",), sets=S("evaluation.gt_radius_m=1e200"),
             why="debatable: inf compares fine, but r^2 is a derived quantity that must be "
                 "representable (issue 12)"),
        Case("a18", "negative network.latency", ("network.latency",),
             sets=S("network.latency=-5ms")),
        Case("a19", "negative service.fixed", ("service.fixed",), sets=S("service.fixed=-1us")),
        Case("a20", "negative dataset.fps", ("dataset.fps",), sets=S("dataset.fps=-10")),
        Case("a21", "dataset.fps = 0", ("dataset.fps",), sets=S("dataset.fps=0")),
        Case("a22", "negative verification.request_bytes", ("verification.request_bytes",),
             sets=S("verification.request_bytes=-1")),
        Case("a23", "negative verification.max_distance", ("verification.max_distance",),
             sets=S("verification.max_distance=-0.5")),
        Case("a24", "negative evaluation.gt_radius_m", ("evaluation.gt_radius_m",),
             sets=S("evaluation.gt_radius_m=-5")),
        Case("a25", "Bernoulli loss p = 1.5", ("network.loss",),
             sets=S("network.loss={model: bernoulli, p: 1.5}")),
        Case("a26", "dataset.frames = 0", ("dataset.frames",), sets=S("dataset.frames=0")),
        Case("a27", "negative runs", ("runs",), sets=S("runs=-1")),
        Case("a28", "network.bandwidth = 0Mbps", ("network.bandwidth",),
             sets=S("network.bandwidth=0Mbps")),
        Case("a29", "network.mtu = 20 (below IPv4's 68)", ("network.mtu",),
             sets=S("network.mtu=20")),
        Case("a30", "more robots than frames (robots up to 100000)", ("robots",),
             sets=S("robots={from: 2, to: 100000}")),
        Case("a31", "negative dropout time", ("dropout",), sets=S("dropout=[{robot: 1, at: -1s}]")),
    ]


def yaml_structure():
    def case(id_, name, expect, why=""):
        return Case(id_, name.replace("_", " ") + " (bad_inputs/yaml/" + name + ".yaml)", expect,
                    base="yaml/" + name + ".yaml", why=why)
    deep = 100000
    return [
        case("b01", "two_runs_keys", ("runs", "two_runs_keys.yaml")),
        case("b02", "duplicate_nested_key", ("network.latency",)),
        case("b03", "second_document", ("second_document.yaml", "document"),
             why="a reader that takes the first document ignores the rest silently"),
        Case("b04", "a directory given as the config", ("b04dir", "director"),
             argv=["run", "{case}/b04dir", "--quiet", "--out", "out"],
             files=lambda d: (d.parent / "b04dir").mkdir(exist_ok=True),
             why="the error must name the directory and say it is one (issue 12)"),
        Case("b05", "an empty config file", ("empty.yaml",),
             argv=["run", "{in}/empty.yaml", "--quiet", "--out", "out"],
             files=spoil("empty.yaml", ""),
             why="debatable: an empty file could mean `all defaults` (the paper's full sweep, "
                 "minutes); a new user more likely saved the wrong file, so it is an error"),
        Case("b06", "a config of comments only", ("comments.yaml",),
             argv=["run", "{in}/comments.yaml", "--quiet", "--out", "out"],
             files=spoil("comments.yaml", "# runs: 2\n# robots: [2, 3]\n"),
             why="as b05"),
        case("b07", "top_level_list", ("top_level_list.yaml",)),
        case("b08", "syntax_error", ("syntax_error.yaml", "line")),
        case("b09", "alias_bomb", ("strategies",)),
        case("b10", "unknown_key", ("netwrok",),
             why="debatable: unknown keys could be warnings; dvpr rejects them (config.h) so "
                 "that a typo never runs a sweep on defaults"),
        case("b11", "unknown_nested_key", ("network.bandwith",), why="as b10"),
        case("b12", "wrong_type_scalar", ("runs",)),
        case("b13", "wrong_type_map", ("dataset",)),
        case("b14", "null_value", ("runs",),
             why="debatable: a key without a value could mean its default; more likely the "
                 "value was forgotten, and the default of runs is 10"),
        case("b15", "huge_integer", ("runs",)),
        case("b16", "complex_key", ("complex_key.yaml",)),
        case("b17", "yes_as_bool", ("outputs.figures",),
             why="debatable: YAML 1.1 reads `no` as false; dvpr accepts only true/false and "
                 "must say so naming the key"),
        Case("b18", "dataset nested %d lists deep" % deep, ("deep.yaml",),
             argv=["run", "{in}/deep.yaml", "--quiet", "--out", "out"],
             files=spoil("deep.yaml", "name: deep\ndataset: " + "[" * deep + "]" * deep + "\n")),
        Case("b19", "a binary file (an .npy) given as the config", ("desc.npy",),
             argv=["run", "{in}/desc.npy", "--quiet", "--out", "out"],
             files=lambda d: write(d / "desc.npy", npy_bytes(matrix(4, 4)))),
        Case("b20", "--set with a value that is not YAML", ("runs",), sets=S("runs=[1")),
        Case("b21", "--set an index past the end of a list", ("dropout",),
             sets=S("dropout.5.at=1s")),
        Case("b22", "--set a key below a scalar (runs.x)", ("runs",), sets=S("runs.x=1")),
        Case("b23", "--set an unknown section", ("netwrk",), sets=S("netwrk.latency=2ms")),
        Case("b24", "name with a slash", ("name",), sets=S("name=../elsewhere")),
    ]


def files_cases():
    f = "files.yaml"
    c = "centroids.yaml"
    synth_poses = set_key("poses", "poses.txt")
    inf_row = [float("inf")] + [0.5] * 31
    return [
        Case("c01", "centroid file with 16 columns for 32-dim descriptors", ("c_n2_r0.npy",),
             base=c, files=spoil("c_n2_r0.npy", npy_bytes(matrix(2, 16)))),
        Case("c02", "centroid file with NaN", ("c_n3_r0.npy",), base=c,
             files=spoil("c_n3_r0.npy", npy_bytes(matrix(2, 32) + [NAN_ROW]))),
        Case("c03", "centroid file with Inf", ("c_n2_r0.npy",), base=c,
             files=spoil("c_n2_r0.npy", npy_bytes([inf_row] + matrix(1, 32)))),
        Case("c04", "centroid file with 2 rows for 3 robots", ("c_n3_r0.npy",), base=c,
             files=spoil("c_n3_r0.npy", npy_bytes(matrix(2, 32)))),
        Case("c05", "centroid files for run 0 only, runs: 2", ("c_n2_r1.npy",), base=c,
             sets=S("runs=2")),
        Case("c06", "centroid file for 3 robots missing", ("c_n3_r0.npy",), base=c,
             files=lambda d: (d / "c_n3_r0.npy").unlink()),
        Case("c07", "truncated centroid .npy", ("c_n2_r0.npy",), base=c,
             files=spoil("c_n2_r0.npy", npy_bytes(matrix(2, 32))[:150])),
        Case("c08", "truncated descriptor .npy", ("desc.npy",), base=f,
             files=spoil("desc.npy", npy_bytes(matrix(200, 32))[:5000])),
        Case("c09", "descriptor .npy whose header is garbage", ("desc.npy",), base=f,
             files=spoil("desc.npy", b"\x93NUMPY\x01\x00\x40\x00" + bytes(range(200, 256)) +
                         b"\x00\x01\x02\n\n\n\x07\x08" + b"\n" * 2)),
        Case("c10", "descriptor .npy of int32", ("desc.npy",), base=f,
             files=spoil("desc.npy", npy_bytes([[1] * 32] * 200, descr="<i4"))),
        Case("c11", "descriptor .npy with three dimensions", ("desc.npy",), base=f,
             files=spoil("desc.npy", npy_bytes(matrix(200, 32), shape=(200, 4, 8)))),
        Case("c12", "ragged descriptor .csv", ("desc.csv",), base=f,
             edit=set_key("descriptors", "desc.csv"),
             files=spoil("desc.csv", "".join(",".join("%.3f" % v for v in row[:31 if i == 7 else 32])
                                             + "\n" for i, row in enumerate(matrix(200, 32))))),
        Case("c13", "descriptor .csv with NaN", ("desc.csv",), base=f,
             edit=set_key("descriptors", "desc.csv"),
             files=spoil("desc.csv", "".join(",".join("nan" if (i, j) == (9, 3) else "%.3f" % v
                                                      for j, v in enumerate(row)) + "\n"
                                             for i, row in enumerate(matrix(200, 32))))),
        Case("c14", "raw .bin whose size is not a whole number of frames", ("desc.bin",), base=f,
             edit=lambda t: set_key("descriptors", "desc.bin")(t).replace(
                 "  dim: 32\n", "  dim: 32\n  bin_width: 64\n"),
             files=spoil("desc.bin", struct.pack("<%df" % (200 * 64 + 7),
                                                 *([0.25] * (200 * 64 + 7))))),
        Case("c15", "descriptor values of 1e30 (squared distances overflow float)", ("desc.npy",),
             base=f, files=spoil("desc.npy", npy_bytes([[v * 1e30 for v in row]
                                                         for row in matrix(200, 32)])),
             why="issue 12: values whose squared distances would overflow are refused up front"),
        Case("c16", "fewer descriptors (150) than poses (200)", ("desc.npy",), base=f,
             files=spoil("desc.npy", npy_bytes(matrix(150, 32)))),
        Case("c17", "pose file shorter than dataset.frames, synthetic source", ("dataset.frames",),
             edit=synth_poses, files=spoil("poses.txt", kitti_lines(200))),
        Case("c18", "pose file shorter than dataset.frames, files source", ("dataset.frames",),
             base=f, sets=S("dataset.frames=300"), forbid=("dataset.descriptors",),
             why="the pose file is short, not the descriptors (issue 12: pose-file errors "
                 "labelled dataset.descriptors)"),
        Case("c19", "pose file (150) shorter than the descriptors (200), files source",
             ("poses.txt",), base=f, files=spoil("poses.txt", kitti_lines(150))),
        Case("c20", "pose line with 11 numbers, synthetic source", ("poses.txt", "dataset.poses"),
             edit=synth_poses, files=spoil("poses.txt", poses_with(300, 5, lambda t: t[:11]))),
        Case("c21", "pose line with 11 numbers, files source", ("poses.txt", "dataset.poses"),
             base=f, forbid=("dataset.descriptors",),
             files=spoil("poses.txt", poses_with(200, 5, lambda t: t[:11]))),
        Case("c22", "pose with NaN", ("poses.txt",), edit=synth_poses,
             files=spoil("poses.txt", poses_with(300, 9, lambda t: t[:3] + ["nan"] + t[4:]))),
        Case("c23", "pose translation of 1e300", ("poses.txt",), edit=synth_poses,
             files=spoil("poses.txt", poses_with(300, 250, lambda t: t[:3] + ["1e300"] + t[4:])),
             why="issue 12: squared distances of such positions overflow"),
        Case("c24", "empty pose file", ("poses.txt",), edit=synth_poses,
             files=spoil("poses.txt", "")),
        Case("c25", "pose file missing", ("dataset.poses",), edit=synth_poses,
             files=lambda d: (d / "poses.txt").unlink()),
        Case("c26", "descriptor file missing", ("dataset.descriptors",), base=f,
             files=lambda d: (d / "desc.npy").unlink()),
        Case("c27", "descriptor path is a directory", ("dataset.descriptors", "folder"),
             base=f, why="`file not found` misleads: it is there, as a folder (as b04)",
             files=lambda d: ((d / "desc.npy").unlink(), (d / "desc.npy").mkdir())),
        Case("c28", "descriptor file with an unknown extension", ("desc.txt",), base=f,
             edit=set_key("descriptors", "desc.txt"), files=spoil("desc.txt", "1 2 3\n")),
        Case("c29", "training.source files without training.descriptors",
             ("training.descriptors",), base=f, sets=S("training.source=files")),
        Case("c30", "training descriptors with NaN", ("train.npy",), base=f,
             sets=S("training={source: files, descriptors: train.npy}"),
             files=spoil("train.npy", npy_bytes(matrix(50, 32) + [NAN_ROW]))),
        Case("c31", "training descriptors narrower than dataset.dim", ("train.npy",), base=f,
             sets=S("training={source: files, descriptors: train.npy}"),
             files=spoil("train.npy", npy_bytes(matrix(50, 16)))),
        Case("c32", "dataset.dim larger than the descriptors", ("desc.npy", ("dataset.dim", "dim 64")),
             base=f, sets=S("dataset.dim=64"),
             why="the file and the value of dim are enough to fix it; the full key is better"),
        Case("c33", "pose file of binary garbage", ("poses.txt",), edit=synth_poses,
             files=spoil("poses.txt", bytes(range(256)) * 4)),
        Case("c34", "descriptor .npy header with line breaks and a bad value", ("desc.npy",),
             base=f, files=spoil("desc.npy", npy_with_header(
                 "{'descr': '<f4',\n 'fortran_order': Maybe,\n 'shape': (200, 32), }",
                 matrix(200, 32)))),
    ]


def robots_cases():
    links = lambda v: S("network.links=" + v)
    return [
        Case("d01", "link override between robots 0 and 5 (teams of 2 and 3)", ("network.links",),
             sets=links("[{src: 0, dst: 5, latency: 10ms}]")),
        Case("d02", "loss override from robot 7 (teams of 2 and 3)", ("network.links",),
             sets=links("[{src: 7, dst: 0, loss: {model: bernoulli, p: 0.5}}]")),
        Case("d03", "link override between robots 1 and 2 with robots: [2]", ("network.links",),
             sets=links("[{src: 1, dst: 2, latency: 10ms}]") + S("robots=[2]")),
        Case("d04", "link override from a robot to itself", ("network.links",),
             sets=links("[{src: 1, dst: 1, latency: 10ms}]")),
        Case("d05", "negative robot in a link override", ("network.links",),
             sets=links("[{src: -1, dst: 1, latency: 10ms}]")),
        Case("d06", "latency override on an ideal network", ("network.links",),
             sets=links("[{src: 0, dst: 1, latency: 10ms}]") + S("network.model=ideal")),
        Case("d07", "dropout of robot 5 (teams of 2 and 3)", ("dropout",),
             sets=S("dropout=[{robot: 5, at: 1s}]")),
        Case("d08", "dropout of robot -1", ("dropout",), sets=S("dropout=[{robot: -1, at: 1s}]")),
        Case("d09", "link override naming robot 2 (in the team of 3 only)", success=True,
             sets=links("[{src: 0, dst: 2, latency: 10ms}]"),
             why="debatable: robot 2 is in the team of 3, so the override is not outside every "
                 "team (issue 12); like a dropout (config.h) it should apply to the teams that "
                 "have the robot"),
        Case("d10", "dropout of robot 2 (in the team of 3 only)", success=True,
             sets=S("dropout=[{robot: 2, at: 5s}]"),
             why="documented: a dropout applies to the teams that have the robot (config.h)"),
    ]


def cli_cases():
    run = lambda *a: ["run", "{config}", "--quiet", "--out", "out", *a]
    return [
        Case("e01", "--threads abc", ("--threads",), argv=run("--threads", "abc"), exit=2),
        Case("e02", "--threads -3", ("--threads",), argv=run("--threads", "-3"), exit=2),
        Case("e03", "--threads 1.5", ("--threads",), argv=run("--threads", "1.5"), exit=2),
        Case("e04", "--threads 99999999999", ("--threads",), argv=run("--threads", "99999999999"),
             exit=2),
        Case("e05", "--threads ''", ("--threads",), argv=run("--threads", ""), exit=2),
        Case("e06", "--out ''", ("--out",),
             argv=["run", "{config}", "--quiet", "--out", ""], exit=2),
        Case("e07", "--out without a value", ("--out",), argv=["run", "{config}", "--out"], exit=2),
        Case("e08", "an unknown flag", ("--frobnicate",), argv=run("--frobnicate"), exit=2),
        Case("e09", "a config file that does not exist", ("nothere.yaml",),
             argv=["run", "{in}/nothere.yaml", "--quiet", "--out", "out"]),
        Case("e10", "dvpr run without a config", ("CONFIG",), argv=["run", "--quiet"], exit=2),
        Case("e11", "two config files", ("second.yaml",),
             argv=run("{in}/second.yaml"), files=spoil("second.yaml", "runs: 1\n"), exit=2),
        Case("e12", "--set without '='", ("--set",), argv=run("--set", "runs"), exit=2,
             why="debatable: a malformed flag is a usage error (2); a bad value for a well-formed "
                 "--set is a config error (1, b20)"),
        Case("e13", "--set with an empty key path", ("--set",), argv=run("--set", "=3"), exit=2,
             why="as e12"),
        Case("e14", "--out is an existing regular file", ("e14/out",), prior="file",
             argv=["run", "{config}", "--quiet", "--out", "{case}/out"],
             why="the file must stay as it was"),
        Case("e15", "--out below a regular file", ("base.yaml",),
             argv=["run", "{config}", "--quiet", "--out", "{in}/base.yaml/out"]),
        Case("e16", "an unknown subcommand", ("runn",), argv=["runn", "{config}"], exit=2),
    ]


def no_file(name):
    return lambda out: [name + " left from the earlier run"] if (out / name).exists() else []


def result_folder_cases():
    return [
        Case("f01", "config error (runs=0) into an earlier result folder", ("runs",),
             sets=S("runs=0"), prior="base.yaml"),
        Case("f02", "centroid file of the wrong width into an earlier result folder",
             ("c_n2_r0.npy",), base="centroids.yaml", prior="centroids.yaml",
             files=spoil("c_n2_r0.npy", npy_bytes(matrix(2, 16)))),
        Case("f03", "service.fixed = 2562047h into an earlier result folder", ("service.fixed",),
             sets=S("service.fixed=2562047h"), prior="base.yaml"),
        Case("f04", "link override outside every team into an earlier result folder",
             ("network.links",), sets=S("network.links=[{src: 0, dst: 5}]"), prior="base.yaml"),
        Case("f05", "a later run with queries off", success=True, prior="base.yaml",
             sets=S("outputs.queries=false"), check=no_file("queries.csv"),
             why="a result folder describes one run (docs/design.md 6): replaced whole, or the run "
                 "refuses with one line and leaves it as it was (issue 12: choose one)"),
        Case("f06", "a later run with fewer robots", success=True, prior="base.yaml",
             sets=S("robots=[2]"), check=no_file("centroids/centroids_n3_r0.npy"), why="as f05"),
        Case("f07", "a later run with messages off after one with messages on", success=True,
             prior="base.yaml+messages", check=no_file("messages.csv"), why="as f05"),
        Case("f08", "a run interrupted (SIGINT) at its first write into an earlier result folder",
             (), interrupt=True, prior="base.yaml", sets=S("dataset.frames=1500", "robots=[2, 3, 4, 5]"),
             why="Ctrl-C must leave the earlier folder as it was and no temporary files (SIGKILL "
                 "cannot be cleaned up after, so it is not tried)"),
        Case("f09", "a late failure into --out a/b/out (parents do not exist)", ("c_n2_r0.npy",),
             base="centroids.yaml", argv=["run", "{config}", "--quiet", "--out", "a/b/out"],
             files=spoil("c_n2_r0.npy", npy_bytes(matrix(2, 16))),
             why="debatable: parent folders created for a run that then fails are left behind"),
    ]


def triples(rows):
    """Binary BoW triples (frame int32, word int32, weight float32), little-endian (docs/bow.md)."""
    return b"".join(struct.pack("<iif", f, w, x) for f, w, x in rows)


def bow_lines(n):
    return "".join("%d:1 %d:2\n" % (i % 7, 10 + i % 5) for i in range(n))


BOW = ("protocols=[paper]", "strategies=[bow_decentralized]")


def later_keys_cases():
    """Keys added after the catalogue was first written: start_time, failover, dataset.bow."""
    return [
        Case("g01", "start_time without its time zone", ("start_time",), sets=S("start_time=2011-10-03T12:00:00")),
        Case("g02", "start_time before 1970", ("start_time",), sets=S("start_time=1969-12-31T23:59:59Z")),
        Case("g03", "failover.timeout shorter than its heartbeat period", ("failover.timeout",),
             sets=S("failover.enabled=true", "failover.heartbeat_period=500ms", "failover.timeout=100ms")),
        Case("g04", "failover.heartbeat_period = 0", ("failover.heartbeat_period",),
             sets=S("failover.enabled=true", "failover.heartbeat_period=0s")),
        Case("g05", "dataset.bow text file with a bad pair on line 3", ("bow.txt", "line 3"),
             sets=S(*BOW, "dataset.bow=bow.txt"),
             files=spoil("bow.txt", bow_lines(2) + "3:x\n" + bow_lines(297))),
        Case("g06", "dataset.bow text file with 299 lines for 300 frames", ("dataset.bow", "299"),
             sets=S(*BOW, "dataset.bow=bow.txt"), files=spoil("bow.txt", bow_lines(299))),
        Case("g07", "dataset.bow binary file of 13 bytes", ("bow.bin", "13 bytes"),
             sets=S(*BOW, "dataset.bow=bow.bin"), files=spoil("bow.bin", triples([(0, 1, 1.0)]) + b"x")),
        Case("g08", "dataset.bow binary triple with word 10^7", ("bow.bin", "triple 1"),
             sets=S(*BOW, "dataset.bow=bow.bin"),
             files=spoil("bow.bin", triples([(299, 1, 1.0), (0, 10000000, 1.0)]))),
        Case("g09", "dataset.bow binary triple with a NaN weight", ("bow.bin", "weight"),
             sets=S(*BOW, "dataset.bow=bow.bin"),
             files=spoil("bow.bin", triples([(299, 1, 1.0), (3, 2, float("nan"))]))),
        Case("g10", "dataset.bow that does not exist", ("dataset.bow", "nope.bin"),
             sets=S(*BOW, "dataset.bow=nope.bin")),
        Case("g11", "dataset.synthetic_bow.features = 0", ("dataset.synthetic_bow.features",),
             sets=S(*BOW, "dataset.synthetic_bow.features=0")),
        Case("g12", "dataset.synthetic_bow.common_words = -1", ("dataset.synthetic_bow.common_words", "-1"),
             sets=S(*BOW, "dataset.synthetic_bow.common_words=-1")),
        Case("g13", "dataset.synthetic_bow.common_words = the vocabulary (100000)",
             ("dataset.synthetic_bow.common_words", "99999"),
             sets=S(*BOW, "dataset.synthetic_bow.common_words=100000")),
        Case("g14", "dataset.synthetic_bow.common_share = 1.5", ("dataset.synthetic_bow.common_share", "[0, 1]"),
             sets=S(*BOW, "dataset.synthetic_bow.common_share=1.5")),
        Case("g15", "dataset.synthetic_bow.common_share = 0.5 without common words",
             ("dataset.synthetic_bow.common_share", "common_words"),
             sets=S(*BOW, "dataset.synthetic_bow.common_share=0.5")),
        Case("g16", "dataset.synthetic_bow.view_sector_deg = 0", ("dataset.synthetic_bow.view_sector_deg", "(0, 360]"),
             sets=S(*BOW, "dataset.synthetic_bow.view_sector_deg=0")),
        Case("g17", "dataset.synthetic_bow.view_sector_deg = 361",
             ("dataset.synthetic_bow.view_sector_deg", "(0, 360]"),
             sets=S(*BOW, "dataset.synthetic_bow.view_sector_deg=361")),
    ]


RADIO = ("network.model=radio", "network.routing=shortest_path")


def radio_cases():
    """Issue 33's radio: ranges, routing, store-and-forward's hold sizes, a propagation model given
    another's keys, a radio whose positions cannot be read, radio keys without a radio."""
    return [
        Case("g18", "network.radio.range = 0m", ("network.radio.range", "(0m"), sets=S(*RADIO, "network.radio.range=0m")),
        Case("g19", "network.radio.range = -5m", ("network.radio.range", "-5m"),
             sets=S(*RADIO, "network.radio.range=-5m")),
        Case("g20", "network.radio.range = .nan", ("network.radio.range", ".nan"),
             sets=S(*RADIO, "network.radio.range=.nan")),
        Case("g21", "network.radio.range = 200 (no unit)", ("network.radio.range", "unit"),
             sets=S(*RADIO, "network.radio.range=200")),
        Case("g22", "network.routing = flooding (unknown)", ("network.routing", "flooding"),
             sets=S("network.model=radio", "network.routing=flooding")),
        Case("g23", "link_state routing with hello = 0s", ("network.routing.hello",),
             sets=S("network.model=radio", "network.routing={kind: link_state, hello: 0s}")),
        Case("g24", "store_and_forward hold_bytes = 0B", ("network.disconnected.hold_bytes", "0B"),
             sets=S(*RADIO, "network.disconnected={kind: store_and_forward, hold_bytes: 0B}")),
        Case("g25", "store_and_forward hold_bytes = 2048GiB (above 1024GiB)", ("network.disconnected.hold_bytes",),
             sets=S(*RADIO, "network.disconnected={kind: store_and_forward, hold_bytes: 2048GiB}")),
        Case("g26", "store_and_forward hold_bytes = -1MB", ("network.disconnected.hold_bytes", "-1MB"),
             sets=S(*RADIO, "network.disconnected={kind: store_and_forward, hold_bytes: -1MB}")),
        Case("g27", "store_and_forward hold_time = 0s", ("network.disconnected.hold_time",),
             sets=S(*RADIO, "network.disconnected={kind: store_and_forward, hold_time: 0s}")),
        Case("g28", "propagation log_distance given a range", ("network.radio.range", "log_distance"),
             sets=S(*RADIO, "network.radio={propagation: log_distance, range: 200m}")),
        Case("g29", "propagation range given log_distance keys", ("network.radio.log_distance",),
             sets=S(*RADIO, "network.radio={propagation: range, log_distance: {exponent: 3}}")),
        Case("g30", "log_distance sensitivity_dbm = .nan", ("network.radio.log_distance.sensitivity_dbm",),
             sets=S(*RADIO, "network.radio={propagation: log_distance, log_distance: {sensitivity_dbm: .nan}}")),
        Case("g31", "a radio whose pose file has a NaN (a position that cannot be known)", ("poses.txt", "NaN"),
             sets=RADIO, edit=set_key("poses", "poses.txt"),
             files=spoil("poses.txt", poses_with(300, 9, lambda t: t[:3] + ["nan"] + t[4:]))),
        Case("g32", "network.radio without model radio", ("network.radio", "model radio"),
             sets=S("network.radio={range: 200m}")),
        Case("g33", "routing shortest_path without model radio", ("network.routing", "model radio"),
             sets=S("network.routing=shortest_path")),
        Case("g34", "outputs.connectivity without model radio", ("outputs.connectivity", "radio"),
             sets=S("outputs.connectivity=true")),
    ]


def checks_before_work_cases():
    """Issue 31: configs that would make a run meaningless or too large, refused before it starts."""
    return [
        Case("h01", "failover.timeout shorter than heartbeat period + a heartbeat's delay "
             "(100ms + 2.0728ms at 10Mbps 2ms)", ("failover.timeout", "heartbeat"),
             sets=S("failover.enabled=true", "failover.heartbeat_period=100ms", "failover.timeout=101ms")),
        Case("h02", "one robot dropped twice", ("dropout[1].robot", "once"),
             sets=S("dropout=[{robot: 1, at: 1s}, {robot: 1, at: 2s}]")),
        Case("h03", "dropout after the run of 3 robots ends (100 frames at 10 fps: 10 s)", ("dropout[0].at", "10s"),
             sets=S("dropout=[{robot: 1, at: 12s}]")),
        Case("h04", "dataset.bow text file without a single word", ("bow.txt", "no frame has a word"),
             sets=S(*BOW, "dataset.bow=bow.txt"), files=spoil("bow.txt", "-\n" * 300)),
        Case("h05", "dataset.bow text weight 1e-50 (0 in float32)", ("bow.txt", "float32"),
             sets=S(*BOW, "dataset.bow=bow.txt"), files=spoil("bow.txt", "1:1e-50\n" + bow_lines(299))),
        Case("h06", "dataset.bow binary file whose weights are all 0", ("bow.bin", "no frame has a word"),
             sets=S(*BOW, "dataset.bow=bow.bin"), files=spoil("bow.bin", triples([(299, 1, 0.0), (0, 2, 0.0)]))),
        Case("h07", "a sweep of 1.6e6 runs (runs = 100000, three latencies)", ("runs", "--allow-large"),
             sets=S("runs=100000", "network.latency=[1ms, 2ms, 3ms]")),
    ]


# ---------------------------------------------------------------------------------------------
# Issue 31: hostile input. The canary file an injected command would create.
CANARY = "PWNED"
INJECT = "'; touch PWNED; ' `touch PWNED` $(touch PWNED)"


def no_canary(out_dir):
    """A success check: no command of a name or path ran (the canary is nowhere in the case)."""
    return ["an injected command ran (%s)" % p.relative_to(out_dir.parent)
            for p in out_dir.parent.rglob(CANARY)]


def with_name(name):
    """edit: the config's name, double-quoted in YAML (the name holds no backslash or double quote)."""
    return lambda text: re.sub(r"(?m)^name: .*$", lambda m: 'name: "' + name + '"', text)


def link(target, at):
    """setup: a symbolic link at case_dir/at to case_dir/target (made if absent)."""
    def make(case_dir):
        t = case_dir / target
        if not t.exists():
            t.mkdir(parents=True)
        p = case_dir / at
        if p.is_symlink() or p.is_file():
            p.unlink()
        elif p.exists():
            import shutil
            shutil.rmtree(p)
        p.symlink_to(t)
    return make


def hostile_cases():
    """Issue 31: names and paths with shell syntax, planted links, foreign files in a result
    folder, outputs onto a run's own files, LCM URLs that are not a team's, output places that
    cannot work, a sweep too large; each one line naming what it should, nothing written."""
    figures = ("outputs.figures=true",)
    return [
        Case("i01", "config name with quotes, backquotes, $(...) and ';' (figures drawn)", success=True,
             edit=with_name("it's" + INJECT), sets=S(*figures), check=no_canary,
             why="the name is text: nothing runs, the figures are drawn"),
        Case("i02", "config path and --out with quotes, backquotes, $(...) and ';' (figures drawn)", success=True,
             argv=["run", "{in}/c" + INJECT + ".yaml", "--quiet", "--out", "out/o" + INJECT, "--set", figures[0]],
             files=lambda d: write(d / ("c" + INJECT + ".yaml"), (d / "base.yaml").read_text()),
             setup=lambda d: (d / "out").mkdir(), check=no_canary),
        Case("i03", "dvpr plot of a folder whose figures is a link out of it", ("figures",),
             argv=["plot", "out"], prior="base.yaml", setup=link("elsewhere", "out/figures")),
        Case("i04", "dvpr replay --out onto a link to the run's config.yaml", ("page.html",),
             argv=["replay", "out", "--out", "out/page.html"], prior="base.yaml+messages",
             setup=lambda d: (d / "out" / "page.html").symlink_to(d / "out" / "config.yaml")),
        Case("i05", "a user's NOTES.txt in the result folder a rerun would replace", ("NOTES.txt",),
             prior="base.yaml", setup=lambda d: write(d / "out" / "NOTES.txt", "mine\n")),
        Case("i06", "a user's analysis/ folder in the result folder", ("analysis",),
             prior="base.yaml", setup=lambda d: write(d / "out" / "analysis" / "a.txt", "mine\n")),
        Case("i07", "dvpr replay --out onto the run's own runs.csv", ("runs.csv",),
             argv=["replay", "out", "--out", "out/runs.csv"], prior="base.yaml+messages"),
        Case("i08", "dvpr launch --lcm memq:// (not a team's provider)", ("--lcm", "udpm"), exit=2,
             argv=["launch", "--config", "{config}", "--robots", "2", "--out", "out", "--lcm", "memq://"]),
        Case("i09", "dvpr agent --lcm file://X?mode=w (would overwrite X)", ("--lcm", "udpm"), exit=2,
             argv=["agent", "--config", "{config}", "--robot", "0", "--robots", "2",
                   "--lcm", "file://{case}/x.log?mode=w"]),
        Case("i10", "--out a mount point (/proc)", ("/proc", "mount point"),
             argv=["run", "{config}", "--quiet", "--out", "/proc"]),
        Case("i11", "--out where nothing can be made (/sys/dvpr_out)", ("/sys/dvpr_out",),
             argv=["run", "{config}", "--quiet", "--out", "/sys/dvpr_out"]),
        Case("i12", "--out inside a file (in/poses.txt/out)", ("poses.txt",),
             argv=["run", "{config}", "--quiet", "--out", "{in}/poses.txt/out"]),
        Case("i13", "a valid 250-character --out", success=True,
             argv=["run", "{config}", "--quiet", "--out", "out/" + "n" * 250],
             setup=lambda d: (d / "out").mkdir(), check=lambda o: [] if (o / ("n" * 250) / "runs.csv").exists()
             else ["no runs.csv in the 250-character folder"],
             why="the temporary name beside it must stay short"),
        Case("i14", "a sweep of 8e5 runs of 100 robots on 4541 frames (about 100 h on 2 cores)",
             ("--allow-large",), sets=S("dataset.frames=4541", "robots=[100]", "runs=100000",
                                       "strategies=[decentralized, broadcast, multi_probe_2, sample_c4]"),
             why="under 10^6 runs, but 8e5 x 0.93 s by the time model (docs/config.md 'Sweep size')"),
    ] + secret_cases() + issue53_cases()


HEX_SECRET = "00112233445566778899aabbccddeeff" * 2


def agent_with_secret(secret):
    return ["agent", "--config", "{config}", "--robot", "0", "--robots", "2", "--team-secret", secret]


def private(name, content, mode=0o600):
    """files: a secret file `name` in the case's inputs with `mode`."""
    def make(in_dir):
        write(in_dir / name, content)
        os.chmod(in_dir / name, mode)
    return make


def secret_cases():
    """Issue 53: the team's secret file of `dvpr agent` (docs/security.md): each file an agent
    must not trust is one line naming --team-secret, the file and what is wrong; nothing starts."""
    return [
        Case("i15", "dvpr agent without --team-secret", ("--team-secret", "required"), exit=2,
             argv=["agent", "--config", "{config}", "--robot", "0", "--robots", "2"]),
        Case("i16", "--team-secret a FIFO nobody writes to", ("--team-secret", "FIFO, not a regular file"),
             argv=agent_with_secret("{in}/fifo"), files=lambda d: os.mkfifo(d / "fifo"),
             why="opened without blocking, refused by its type: no hang"),
        Case("i17", "--team-secret /dev/zero", ("--team-secret", "/dev/zero", "device, not a regular file"),
             argv=agent_with_secret("/dev/zero")),
        Case("i18", "--team-secret a loop of symbolic links", ("--team-secret", "symbolic link"),
             argv=agent_with_secret("{in}/loop_a"),
             files=lambda d: (os.symlink(d / "loop_b", d / "loop_a"), os.symlink(d / "loop_a", d / "loop_b"))),
        Case("i19", "--team-secret readable by everyone (mode 0644)", ("--team-secret", "mode 0644"),
             argv=agent_with_secret("{in}/team.secret"), files=private("team.secret", HEX_SECRET + "\n", 0o644)),
        Case("i20", "--team-secret with a byte-order mark before its digits", ("--team-secret", "hexadecimal"),
             argv=agent_with_secret("{in}/team.secret"),
             files=private("team.secret", "\ufeff" + HEX_SECRET[3:] + "\n")),
        Case("i21", "dvpr launch --hold-bytes 0", ("--hold-bytes",), exit=2,
             argv=["launch", "--config", "{config}", "--robots", "2", "--out", "out", "--hold-bytes", "0"]),
        Case("i22", "a `name` of 120 000 characters", ("name", "at most 255 bytes"),
             edit=lambda t: t.replace("name: base", "name: " + "n" * 120000),
             why="it names the output folder: one short line naming the key, not 120 kB"),
        Case("i23", "network.radio.range 0.4mm (rounds to 0 at 1 mm)", ("network.radio.range", "rounds to 0"),
             sets=S("network.model=radio", "network.radio={range: 0.4mm}")),
        Case("i24", "a FIFO as a robot's trajectory (dataset.trajectories[0].poses)",
             ("dataset.trajectories[0].poses", "FIFO, not a regular file"),
             argv=["run", "{config}", "--quiet", "--out", "out", "--set", "robots=[2]", "--set", "dataset.frames=all",
                   "--set", "dataset.trajectories=[{poses: '{in}/fifo', format: tum}, {poses: '{in}/fifo', format: tum}]"],
             files=lambda d: os.mkfifo(d / "fifo"), why="named by its type, never opened: no hang"),
    ]


# ---------------------------------------------------------------------------------------------
# Issue 53, the rest of its list: costs the sweep-size check must see, silent numbers, file errors,
# replay of the new folders. Each is what one `dvpr` invocation shows; docs/bad_inputs.md lists the
# cases of the issue that are not here and why.

KITTI_NS = 1317643200000000000  # 2011-10-03T12:00:00Z, KITTI 00's day, in nanoseconds


def trajectory_csv(first, n, t0, dt, bom=False, times=None):
    """A Kimera-Multi CSV trajectory: poses first..first+n-1 of KITTI 00 (x, y, z of each, the
    identity rotation), timestamp_ns t0 + i dt; times maps a 0-based pose to its field as written;
    bom puts a UTF-8 byte-order mark before the header."""
    lines = kitti_lines(first + n).splitlines()[first:]
    rows = ["timestamp_ns,x,y,z,qw,qx,qy,qz"]
    for i, line in enumerate(lines):
        v = line.split()
        stamp = (times or {}).get(i, str(t0 + i * dt))
        rows.append("%s,%s,%s,%s,1,0,0,0" % (stamp, v[3], v[7], v[11]))
    return ("\ufeff" if bom else "") + "\n".join(rows) + "\n"


def two_robot_files(robot0, robot1="r1.csv"):
    """sets: a team of 2 driving their own CSV trajectories (names relative to the config's folder)."""
    return S("robots=[2]", "dataset.frames=all",
             "dataset.trajectories=[{poses: '%s', format: csv}, {poses: '%s', format: csv}]" % (robot0, robot1))


def trajectories(robot0_text):
    """files: robot 0's trajectory r0.csv (robot0_text) and a good r1.csv, 150 poses at 10 Hz each."""
    def make(in_dir):
        if robot0_text is not None:
            write(in_dir / "r0.csv", robot0_text)
        write(in_dir / "r1.csv", trajectory_csv(150, 150, KITTI_NS, 100000000))
    return make


def harness_dvpr():
    """The dvpr binary bad_inputs.py was given (its first positional argument): a case whose input
    is a result folder the catalogue's base configs cannot make (a wifi run) has its setup make it."""
    args = iter(sys.argv[1:])
    for a in args:
        if a in ("--json", "--before", "--only", "--jobs"):
            next(args, None)
        elif not a.startswith("-"):
            return Path(a).resolve()
    raise RuntimeError("catalogue: no dvpr binary among bad_inputs.py's arguments")


def result_folder(config, *sets, then=None):
    """setup: `dvpr run in/CONFIG --out out` with sets (a folder the base configs' priors cannot
    be: a prior named `out` turns any error naming `out` into an accepted refusal), then then(case_dir)."""
    def make(case_dir):
        argv = [str(harness_dvpr()), "run", str(case_dir / "in" / config), "--quiet", "--out", "out"]
        for s in sets:
            argv += ["--set", s]
        p = subprocess.run(argv, cwd=case_dir, capture_output=True, timeout=60)
        if p.returncode != 0:
            raise RuntimeError("setup run failed: " + p.stderr.decode("utf-8", "replace"))
        if then:
            then(case_dir)
    return make


def with_hops(case_dir):
    """then: messages.csv gains a radio's hops column, 1 everywhere and 2 on line 3 (a delivered copy)."""
    path = case_dir / "out" / "messages.csv"
    lines = path.read_text().splitlines()
    rows = [lines[0] + ",hops"] + [line + (",2" if i == 2 else ",1") for i, line in enumerate(lines[1:], 1)]
    write(path, "\n".join(rows) + "\n")


def descriptors_moved(case_dir):
    """then: the run's descriptor file moves to in/moved/ (its config.yaml still names the old place)."""
    (case_dir / "in" / "moved").mkdir()
    os.rename(case_dir / "in" / "desc.npy", case_dir / "in" / "moved" / "desc.npy")


def csv_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def a_replay_page(out_dir):
    return [] if list(out_dir.glob("replay_*.html")) else ["no replay page"]


def copies_held(out_dir):
    """i26: some copies were held (the case holds what it claims); the harness's 60 s bound the rest."""
    held = sum(int(r["held_copies"]) for r in csv_rows(out_dir / "radio.csv"))
    return [] if held > 0 else ["no copy held: the radios met"]


def robot0_silent(out_dir):
    """i33: robot 0's only window opens after the run: every copy it sends or is sent is lost."""
    rows = [r for r in csv_rows(out_dir / "links.csv") if "0" in (r["src"], r["dst"])]
    if not rows:
        return ["no link of robot 0 in links.csv"]
    return ["the talk window was not applied: %s of %s copies %s->%s delivered" % (
        int(r["messages"]) - int(r["dropped"]), r["messages"], r["src"], r["dst"])
        for r in rows if r["dropped"] != r["messages"]][:1]


def all_poses(out_dir):
    """i34: every pose of both files was read (150 each), the one behind the mark too."""
    bad = [r["queries"] for r in csv_rows(out_dir / "runs.csv") if r["protocol"] == "paper" and r["queries"] != "300"]
    return ["%s queries, expected 300" % q for q in bad]


def issue53_cases():
    """Issue 53's list (docs/bad_inputs.md, "Issue 53: the catalogue"): each is one line naming the
    key or file and what is wrong, or a correct result."""
    radio = ("network.model=radio",)
    default_sweep = ("robots={from: 2, to: 20}", "runs=10", "dataset.frames=all")
    never_meet = radio + ("network.routing=shortest_path", "network.radio={range: 1m}")
    maxima = "dataset.synthetic_bow={features: 100000, landmark_density: 10, range_m: 1000}"
    return [
        Case("i25", "link_state beacons every microsecond (hello and topology 1us) on the default sweep",
             ("network.routing", "--allow-large"),
             sets=S(*radio, "network.routing={kind: link_state, hello: 1us, topology: 1us}", *default_sweep),
             why="9.5e9 transmissions a run of 20 robots (2e4 h): refused before any run starts"),
        Case("i26", "store_and_forward holding 100000 h on radios 1 m apart at most (they never meet)",
             success=True, sets=S(*never_meet, "network.disconnected={kind: store_and_forward, hold_time: 100000h}"),
             check=copies_held,
             why="bounded: what is still held when the team's last frame is taken is dropped then, not "
                 "asked again every 100 ms for 100000 h (the harness's 60 s would end it)"),
        Case("i27", "a staggered team 100000 h apart with outputs.connectivity",
             ("dataset.scenario", "outputs.connectivity", "--allow-large"),
             sets=S(*radio, "dataset.scenario={kind: staggered, offset: 100000h}", "robots=[2]",
                    "outputs.connectivity=true"),
             why="3.6e9 connectivity steps, 6200 GiB a run: refused naming the plan's key"),
        Case("i28", "verification.request_bytes: 1GiB (the documented maximum) on the default sweep",
             ("verification.request_bytes", "--allow-large"),
             sets=S("verification.request_bytes=1GiB", *default_sweep),
             why="21 GiB a run of 20 robots, 2400 s of requests a run: refused on any machine by memory "
                 "or time; on base.yaml's 3 robots it is accepted (6 GiB a run, 161 s) and runs that long"),
        Case("i29", "store_and_forward with routing: direct", ("network.disconnected", "network.routing"),
             sets=S(*radio, "network.routing=direct", "network.disconnected={kind: store_and_forward, hold_time: 10s}"),
             why="direct routing never holds a copy: store_and_forward would do nothing, silently"),
        Case("i30", "a talk window of robot 3 with robots: [2, 3]",
             ("network.schedule", "sched.csv", "line 3", "robot 3"),
             sets=S("network.schedule=sched.csv"), files=spoil("sched.csv", "robot,start_s,end_s\n0,0,5\n3,1,4\n")),
        Case("i31", "a schedule header naming both robot and ROBOT_ID",
             ("network.schedule", "sched.csv", "'robot'", "'ROBOT_ID'"),
             sets=S("network.schedule=sched.csv"), files=spoil("sched.csv", "robot,start_s,end_s,ROBOT_ID\n0,0,5,0\n")),
        Case("i32", "trajectory timestamp_ns in whole seconds (1317643200, 1317643201, ...)",
             ("dataset.trajectories[0]", "r0.csv", "timestamp_ns", "seconds"),
             sets=two_robot_files("r0.csv"), files=trajectories(trajectory_csv(0, 150, 1317643200, 1))),
        Case("i33", "a byte-order mark before a network.schedule header", success=True,
             sets=S("network.schedule=sched.csv"), check=robot0_silent,
             files=spoil("sched.csv", "\ufeffrobot,start_s,end_s\n0,1000,1001\n"),
             why="the mark is skipped: the file is read, robot 0 talks only in [1000 s, 1001 s), after the run"),
        Case("i34", "a byte-order mark before a CSV trajectory's header", success=True,
             sets=two_robot_files("r0.csv"), check=all_poses,
             files=trajectories(trajectory_csv(0, 150, KITTI_NS, 100000000, bom=True)),
             why="the mark is skipped (docs/config.md); before, the header had no column timestamp_ns"),
        Case("i35", "trajectory timestamp_ns 99999999999999999999 on line 3 (overflows int64)",
             ("dataset.trajectories[0]", "r0.csv", "line 3", "timestamp_ns", "out of range"), forbid=("ascending",),
             sets=two_robot_files("r0.csv"),
             files=trajectories(trajectory_csv(0, 150, KITTI_NS, 100000000, times={1: "99999999999999999999"})),
             why="before: capture times not ascending, no file named"),
        Case("i36", "a link to /dev/zero as a robot's trajectory",
             ("dataset.trajectories[0].poses", "zero.csv", "device, not a regular file"), forbid=("not found",),
             sets=two_robot_files("zero.csv"),
             files=lambda d: (trajectories(None)(d), os.symlink("/dev/zero", d / "zero.csv"))),
        Case("i37", "a loop of symbolic links as a robot's trajectory",
             ("dataset.trajectories[0].poses", "loop_a.csv", "loop of symbolic links"), forbid=("not found",),
             sets=two_robot_files("loop_a.csv"),
             files=lambda d: (trajectories(None)(d), os.symlink(d / "loop_b.csv", d / "loop_a.csv"),
                              os.symlink(d / "loop_a.csv", d / "loop_b.csv"))),
        Case("i38", "dvpr replay of a wifi result folder (latency_ms empty)", success=True,
             argv=["replay", "out"], check=a_replay_page,
             setup=result_folder("base.yaml", "network.model=wifi", "network.wifi={rate: 6Mbps}", "robots=[2]",
                                 "outputs.messages=true"),
             why="before: every wifi folder refused, latency_ms: expected a number, got ''"),
        Case("i39", "dvpr replay of a point_to_point messages.csv with hops 2 on line 3",
             ("messages.csv", "line 3", "hops", "no relays"), argv=["replay", "out"],
             setup=result_folder("base.yaml", "outputs.messages=true", then=with_hops),
             why="one transmission is all a point-to-point link makes; the folder is not a prior so "
                 "that the expected words are checked (an error naming out/ passes for a prior)"),
        Case("i40", "dataset.bow a binary BoW file named BOW.BIN", success=True,
             sets=S(*BOW, "dataset.bow=BOW.BIN"),
             files=spoil("BOW.BIN", triples([(f, w, 1.0) for f in range(300)
                                             for w in (f % 7, 10 + f % 5, 100 + f // 3)])),
             why="read as binary triples (.bin in any case); as text it would be refused"),
        Case("i41", "the synthetic BoW world at its maxima on KITTI 00 (4541 frames, 2.1 h to make) "
             "in 78000 paper runs on one thread (22.9 h)", ("dataset.synthetic_bow", "--allow-large"),
             argv=["run", "{config}", "--quiet", "--out", "out", "--threads", "1", "--set", BOW[0], "--set", BOW[1],
                   "--set", "dataset.frames=4541", "--set", "robots=[2]", "--set", "dropout=[]",
                   "--set", "runs=78000", "--set", "dataset.dim=1024", "--set", maxima],
             why="25 h only with the world's 7720 s counted: refused naming it (one thread: the same on "
                 "any machine); the world alone (one run, 2.1 h by the model) is accepted, and whether it "
                 "shows progress needs the run itself, too long for the catalogue"),
        Case("i42", "dvpr replay of a result folder whose descriptor file moved", success=True,
             base="files.yaml", argv=["replay", "out"], check=a_replay_page,
             setup=result_folder("files.yaml", "outputs.messages=true", then=descriptors_moved),
             why="replay reads the run's CSVs and poses, never the descriptors"),
    ]


# ---------------------------------------------------------------------------------------------
# Issue 50, item 1: a team of dataset.trajectories with a descriptor file per robot
# (dataset.trajectories[i].descriptors, dataset.source files), from files.yaml: robot 0 drives
# KITTI 00's poses 0-149 (r0.csv, d0.npy), robot 1 poses 150-299 (r1.csv, d1.npy), 150 x 32 each.

def team_files(d1_rows=150, d1_cols=32, d1_name="d1.npy", d1=True):
    """sets: the team of two robot entries with their own descriptor files (robot 1's named
    d1_name, or none when not d1); files: both trajectories, d0.npy and d1.npy of the given shape."""
    entry1 = "{poses: r1.csv, format: csv%s}" % (", descriptors: %s" % d1_name if d1 else "")
    sets = S("robots=[2]", "dataset.trajectories=[{poses: r0.csv, format: csv, descriptors: d0.npy}, %s]" % entry1)

    def files(in_dir):
        write(in_dir / "r0.csv", trajectory_csv(0, 150, KITTI_NS, 100000000))
        write(in_dir / "r1.csv", trajectory_csv(150, 150, KITTI_NS, 100000000))
        write(in_dir / "d0.npy", npy_bytes(matrix(150, 32, seed=5)))
        write(in_dir / "d1.npy", npy_bytes(matrix(d1_rows, d1_cols, seed=6)))
    return sets, files


def without_dataset_files(text):
    """files.yaml without dataset.poses and dataset.descriptors: the team's entries give them."""
    return re.sub(r"(?m)^  (poses|descriptors): .*\n", "", text)


def team_files_case(id, what, expect, success=False, why="", **shape):
    sets, files = team_files(**shape)
    return Case(id, what, expect, base="files.yaml", sets=sets, files=files, edit=without_dataset_files,
                success=success, why=why)


def team_files_cases():
    r1 = "dataset.trajectories[1].descriptors"
    return [
        team_files_case("j01", "a robot's descriptor file with 149 rows for its 150 poses",
                        (r1, "d1.npy", "149", "r1.csv"), d1_rows=149),
        team_files_case("j02", "robot 1's descriptors 64 wide, robot 0's 32 (dim 32)",
                        (r1, "d1.npy", "64", "dataset.trajectories[0].descriptors", "32"), d1_cols=64,
                        why="the first 32 columns of both would run, but two widths are two kinds of "
                            "descriptor: not comparable, so refused"),
        team_files_case("j03", "robot 1's descriptors 16 wide with dataset.dim 32",
                        (r1, "d1.npy", "dim 32"), d1_cols=16),
        team_files_case("j04", "a robot's descriptor file that is not there",
                        (r1, "gone.npy", "not found"), d1_name="gone.npy"),
        team_files_case("j05", "robot 0's entry names a descriptor file, robot 1's none",
                        (r1, "required", "dataset.trajectories[0]"), d1=False),
        team_files_case("j06", "a team with a descriptor file per robot", (), success=True,
                        why="the control: the same team whose every other case spoils one thing"),
    ]


def catalogue():
    return quantities() + yaml_structure() + files_cases() + robots_cases() + cli_cases() + \
        result_folder_cases() + later_keys_cases() + radio_cases() + checks_before_work_cases() + hostile_cases() + \
        team_files_cases()
