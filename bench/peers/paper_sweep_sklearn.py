#!/usr/bin/python3
"""The paper sweep (docs/design.md section 2) in numpy/scikit-learn: the peer of dvpr's BM_PaperSweep.

  apt-get install python3-sklearn
  nice -n 10 /usr/bin/time -v /usr/bin/python3 bench/peers/paper_sweep_sklearn.py
  /usr/bin/python3 bench/peers/paper_sweep_sklearn.py --robots-to 3 --runs 2   # smoke test

The same work as dvpr's static protocol (experiments/protocols/paper/static_protocol.h), written
the straightforward numpy way: once, the N x N squared-distance matrix of the deployment
(suppression window |i - j| <= 250 set to +inf), the ground truth and the centralized AUC; then
for n = 2..20 robots and 10 runs each (190 fits): scikit-learn KMeans(k = n, k-means++, n_init=1,
tol 1e-4, max_iter 300, algorithm='lloyd') on the 20 000 x 128 training descriptors, every frame
routed to its nearest centroid (robot = centroid, k = n), each query's best match among the
frames routed to its own robot, the decentralized AUC, relative AUC and worst balance ratio.
Data: synthetic_like.py (KITTI 00 positions from data/kitti/00_poses.txt, N = 4541, d = 128),
a stand-in for dvpr's synthetic model, so the AUCs are not dvpr's; the work per step is.
Prints the total wall and CPU seconds and the split between k-means and the rest.
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import synthetic_like  # noqa: E402

WINDOW = 250
RADIUS_SQ = 5.0**2


def suppressed_distances(x):
    """N x N float64 squared L2 distances, +inf inside the suppression window."""
    x = x.astype(np.float64)
    norms = np.einsum("ij,ij->i", x, x)
    d = np.maximum(norms[:, None] + norms[None, :] - 2.0 * (x @ x.T), 0.0)
    idx = np.arange(len(x))
    d[np.abs(idx[:, None] - idx[None, :]) <= WINDOW] = np.inf
    return d


def ground_truth(pos):
    """g(i) < r^2 per query (relevant) and the position distance matrix (for true positives)."""
    p = ((pos[:, None, :] - pos[None, :, :]) ** 2).sum(axis=2)
    idx = np.arange(len(pos))
    masked = np.where(np.abs(idx[:, None] - idx[None, :]) <= WINDOW, np.inf, p)
    return masked.min(axis=1) < RADIUS_SQ, p


def auc(score, match, pos_sq, relevant_count):
    """docs/design.md section 2: rank ranked queries by score, cumulative TP/FP, area under PR."""
    ranked = np.flatnonzero(np.isfinite(score))
    order = ranked[np.argsort(score[ranked], kind="stable")]
    tp = (pos_sq[order, match[order]] < RADIUS_SQ).astype(np.float64)
    tps, fps = np.cumsum(tp), np.cumsum(1.0 - tp)
    precision = tps / (tps + fps + 1e-12)
    recall = tps / (tps + (relevant_count - tps) + 1e-12)
    return float(np.sum(np.diff(recall) * precision[1:]))


def restricted_best(d, routes, robots):
    """Each query's best score and match among the frames routed to its own robot."""
    score = np.full(len(routes), np.inf)
    match = np.zeros(len(routes), dtype=np.int64)
    for r in range(robots):
        members = np.flatnonzero(routes == r)
        if len(members) == 0:
            continue
        sub = d[np.ix_(members, members)]
        best = sub.argmin(axis=1)
        score[members] = sub[np.arange(len(members)), best]
        match[members] = members[best]
    return score, match


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--robots-from", type=int, default=2)
    parser.add_argument("--robots-to", type=int, default=20)
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--poses", default=os.path.join(HERE, "..", "..", "data", "kitti", "00_poses.txt"))
    args = parser.parse_args()
    from sklearn.cluster import KMeans

    start, start_cpu = time.perf_counter(), time.process_time()
    pos = synthetic_like.kitti_positions(args.poses)
    x = synthetic_like.deployment(pos)
    training = synthetic_like.training_diverse(20000)
    d = suppressed_distances(x)
    relevant, pos_sq = ground_truth(pos)
    central_match = d.argmin(axis=1)
    central = auc(d[np.arange(len(x)), central_match], central_match, pos_sq, relevant.sum())
    precompute_s = time.perf_counter() - start
    kmeans_s = rest_s = 0.0
    relative = []
    for n in range(args.robots_from, args.robots_to + 1):
        for run in range(args.runs):
            t0 = time.perf_counter()
            km = KMeans(n_clusters=n, init="k-means++", n_init=1, max_iter=300, tol=1e-4,
                        algorithm="lloyd", random_state=1000 * n + run).fit(training)
            t1 = time.perf_counter()
            routes = km.predict(x)
            score, match = restricted_best(d, routes, n)
            relative.append(auc(score, match, pos_sq, relevant.sum()) / central)
            np.bincount(routes, minlength=n).max() / (len(x) / n)  # worst balance ratio
            kmeans_s += t1 - t0
            rest_s += time.perf_counter() - t1
    wall, cpu = time.perf_counter() - start, time.process_time() - start_cpu
    print(f"N = {len(x)}, d = {x.shape[1]}, R = {relevant.sum()}, central AUC {central:.4f}, "
          f"{len(relative)} runs, mean relative AUC {np.mean(relative):.4f}")
    print(f"total {wall:.1f} s wall, {cpu:.1f} s CPU (all threads); precompute {precompute_s:.1f} s, "
          f"k-means {kmeans_s:.1f} s, routing + restricted search + AUC {rest_s:.1f} s (wall)")


if __name__ == "__main__":
    main()
