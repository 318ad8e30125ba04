#!/usr/bin/env python3
"""Writes the shipped example team of experiments/configs/own_team.yaml, once (issue 50).

Three robots drive stretches of KITTI 00 (data/kitti/00_poses.txt) as a team with data of its own
would come: robot r drives poses 400 r to 400 r + 599 at 10 Hz, starting 20 r seconds after
robot 0, each in its own TUM file (data/own_team/robot<r>.txt: `t x y z qx qy qz qw`, t in seconds
from the robot's first pose, the quaternion of KITTI's rotation), and each with its own descriptor
file (data/own_team/robot<r>.npy, 600 x 32 float32). The descriptors are the project's synthetic
model rendered along the team's poses and times: `dvpr descriptors` on own_team.yaml with
dataset.source synthetic, so the team given through its files and the same team given through the
synthetic source run to the same numbers (TeamPlanCliTest.OwnTeamRunsAsTheSameTeamFromTheSyntheticSource).

    python3 scripts/make_own_team.py build/release/dvpr      # rewrites data/own_team/robot*.{txt,npy}

Standard library only; the output is the same on every run (the model is seeded by the config)."""
import math
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ROBOTS = 3
FIRST_STEP = 400   # robot r's first pose of KITTI 00
POSES = 600        # poses each robot drives (60 s at 10 Hz)
START_STEP_S = 20  # robot r starts 20 r seconds after robot 0 (own_team.yaml's starts)
FPS = 10


def quaternion(r):
    """(qx, qy, qz, qw) of the 3x3 rotation r (rows), Shepperd's method."""
    trace = r[0][0] + r[1][1] + r[2][2]
    if trace > 0:
        s = 2 * math.sqrt(trace + 1)
        return ((r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s, s / 4)
    if r[0][0] > r[1][1] and r[0][0] > r[2][2]:
        s = 2 * math.sqrt(1 + r[0][0] - r[1][1] - r[2][2])
        return (s / 4, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s, (r[2][1] - r[1][2]) / s)
    if r[1][1] > r[2][2]:
        s = 2 * math.sqrt(1 + r[1][1] - r[0][0] - r[2][2])
        return ((r[0][1] + r[1][0]) / s, s / 4, (r[1][2] + r[2][1]) / s, (r[0][2] - r[2][0]) / s)
    s = 2 * math.sqrt(1 + r[2][2] - r[0][0] - r[1][1])
    return ((r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, s / 4, (r[1][0] - r[0][1]) / s)


def tum_lines(kitti, first):
    lines = ["# timestamp x y z qx qy qz qw (KITTI 00 poses %d-%d, seconds from the robot's first pose)"
             % (first, first + POSES - 1)]
    for k in range(POSES):
        v = [float(x) for x in kitti[first + k].split()]
        rot = [v[0:3], v[4:7], v[8:11]]
        q = quaternion(rot)
        lines.append("%.1f %s %s %s %s" % (k / FPS, repr(v[3]), repr(v[7]), repr(v[11]),
                                           " ".join("%.17g" % c for c in q)))
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_own_team.py PATH/TO/dvpr")
    dvpr = Path(sys.argv[1]).resolve()
    out = ROOT / "data" / "own_team"
    kitti = (ROOT / "data" / "kitti" / "00_poses.txt").read_text().splitlines()
    out.mkdir(parents=True, exist_ok=True)
    for r in range(ROBOTS):
        (out / ("robot%d.txt" % r)).write_text(tum_lines(kitti, FIRST_STEP * r))
    # own_team.yaml with the synthetic source: the same team, its descriptors rendered.
    entries = ", ".join("{poses: robot%d.txt, format: tum, start: %ds}" % (r, START_STEP_S * r) for r in range(ROBOTS))
    with tempfile.TemporaryDirectory() as tmp:
        target = Path(tmp) / "descriptors"
        subprocess.run([str(dvpr), "descriptors", str(ROOT / "experiments" / "configs" / "own_team.yaml"),
                        "--out", str(target), "--set", "dataset.source=synthetic",
                        "--set", "dataset.trajectories=[%s]" % entries.replace("robot", str(out) + "/robot")],
                       check=True, stdout=subprocess.DEVNULL)
        for r in range(ROBOTS):
            shutil.copyfile(target / ("robot%d.npy" % r), out / ("robot%d.npy" % r))
    print("wrote %s/robot{0..%d}.{txt,npy}" % (out.relative_to(ROOT), ROBOTS - 1))


if __name__ == "__main__":
    main()
