#!/usr/bin/python3
"""Independent numpy implementation of the paper's static evaluation (docs/design.md section 2).

Written from the specification, not from dvpr's C++, so that tests can check dvpr against it:

  paper_eval.py --poses P.txt --descriptors D.npy --centroids 'c_n{robots}_r{run}.npy' \
      --robots 2 3 5 --runs 2 --radius 5 --window 250 --out result.csv

Writes CSV lines: "centralized,<auc>,<R>" then "<robots>,<run>,<auc>,<relative_auc>,<wbr>".
Centroid c of a run with n robots is owned by robot c mod n.
"""
import argparse

import numpy as np


def positions(pose_file):
    rows = np.loadtxt(pose_file, ndmin=2)
    return rows[:, [3, 7, 11]]  # values 4, 8, 12 (1-based) of each 3x4 [R|t]


def auc_of(dist, pos, relevant, radius):
    """PR AUC with the best match restricted to the finite entries of each row of dist."""
    has_candidate = np.isfinite(dist).any(axis=1)
    best = np.argmin(dist, axis=1)
    score = dist[np.arange(len(dist)), best]
    queries = np.flatnonzero(has_candidate)
    order = queries[np.argsort(score[queries], kind="stable")]
    tp = (((pos[order] - pos[best[order]]) ** 2).sum(axis=1) < radius ** 2).astype(np.float64)
    TP = np.cumsum(tp)
    FP = np.cumsum(1.0 - tp)
    FN = relevant - TP
    precision = TP / (TP + FP + 1e-12)
    recall = TP / (TP + FN + 1e-12)
    return float(np.sum((recall[1:] - recall[:-1]) * precision[1:]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--poses", required=True)
    ap.add_argument("--descriptors", required=True)
    ap.add_argument("--centroids", required=True)
    ap.add_argument("--robots", type=int, nargs="+", required=True)
    ap.add_argument("--runs", type=int, required=True)
    ap.add_argument("--radius", type=float, default=5.0)
    ap.add_argument("--window", type=int, default=250)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()

    pos = positions(a.poses)
    x = np.load(a.descriptors).astype(np.float64)
    n_frames = len(x)
    assert len(pos) == n_frames
    idx = np.arange(n_frames)
    in_window = np.abs(idx[:, None] - idx[None, :]) <= a.window

    d = ((x[:, None, :] - x[None, :, :]) ** 2).sum(axis=2)
    d[in_window] = np.inf
    g = ((pos[:, None, :] - pos[None, :, :]) ** 2).sum(axis=2)
    g[in_window] = np.inf
    relevant = int((g.min(axis=1) < a.radius ** 2).sum())

    central = auc_of(d, pos, relevant, a.radius)
    lines = ["centralized,%.17g,%d" % (central, relevant)]
    for n in a.robots:
        for run in range(a.runs):
            path = a.centroids.replace("{robots}", str(n)).replace("{run}", str(run))
            c = np.load(path).astype(np.float64)
            to_centroid = ((x[:, None, :] - c[None, :, :]) ** 2).sum(axis=2)
            owner = np.argmin(to_centroid, axis=1) % n
            restricted = d.copy()
            restricted[owner[:, None] != owner[None, :]] = np.inf
            auc = auc_of(restricted, pos, relevant, a.radius)
            counts = np.bincount(owner, minlength=n)
            wbr = counts.max() / (n_frames / n)
            lines.append("%d,%d,%.17g,%.17g,%.17g" % (n, run, auc, auc / central, wbr))
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
