#!/usr/bin/python3
"""One k-means fit (k = 11, 20 000 x 128 float32) with FAISS and with scikit-learn, medians of 5.

The peer of dvpr's `BM_KMeans/11` (bench/bench_paper_sweep.cpp); see bench/peers/README.md.
  apt-get install python3-faiss python3-sklearn
  /usr/bin/python3 bench/peers/kmeans_faiss.py            # single-threaded, as dvpr's fit
  /usr/bin/python3 bench/peers/kmeans_faiss.py --threads 2

dvpr's fit (agents/algorithms/kmeans.cpp): k-means++ seeding, Lloyd (Hamerly-accelerated, same fixed
points), at most 300 iterations, stop when the summed squared centroid shift <= 1e-4 x mean
per-dimension variance, or when no label changes; one restart. scikit-learn's KMeans with
init='k-means++', n_init=1, max_iter=300, tol=1e-4, algorithm='lloyd' is the same algorithm and
stopping rule. FAISS's Kmeans has neither k-means++ nor a tolerance: it seeds with k random
points and runs exactly `niter` iterations, so it is timed twice - with its default niter = 25,
and with niter = the iterations scikit-learn needed to converge on the same data. FAISS also
subsamples to max_points_per_centroid x k points by default (256 x 11 = 2816); that is switched
off here so it fits all 20 000 points, as dvpr does.
"""
import argparse
import os
import statistics
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import synthetic_like  # noqa: E402


def median_ms(fit, repetitions):
    """Median wall ms, all wall ms, median CPU ms (this process, all threads), the last result.

    CPU time is quoted beside wall time because a shared, loaded machine stretches wall time."""
    times, cpu = [], []
    result = None
    for _ in range(repetitions):
        start, start_cpu = time.perf_counter(), time.process_time()
        result = fit()
        times.append((time.perf_counter() - start) * 1e3)
        cpu.append((time.process_time() - start_cpu) * 1e3)
    return statistics.median(times), times, statistics.median(cpu), result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--k", type=int, default=11)
    parser.add_argument("--samples", type=int, default=20000)
    parser.add_argument("--repetitions", type=int, default=5)
    parser.add_argument("--threads", type=int, default=1, help="OpenMP/BLAS threads (dvpr's fit: 1)")
    parser.add_argument("--seed", type=int, default=3)
    parser.add_argument("--npy", help="fit these float32 N x d descriptors instead of synthetic ones")
    args = parser.parse_args()

    import faiss
    from sklearn.cluster import KMeans
    from threadpoolctl import threadpool_limits

    x = np.load(args.npy).astype(np.float32) if args.npy else synthetic_like.training_diverse(args.samples)
    x = np.ascontiguousarray(x)
    print(f"data: {x.shape[0]} x {x.shape[1]} float32, k = {args.k}, threads = {args.threads}, "
          f"median of {args.repetitions}")
    faiss.omp_set_num_threads(args.threads)
    with threadpool_limits(limits=args.threads):
        def sk_fit():
            km = KMeans(n_clusters=args.k, init="k-means++", n_init=1, max_iter=300, tol=1e-4,
                        algorithm="lloyd", random_state=args.seed)
            return km.fit(x)
        ms, times, cpu, km = median_ms(sk_fit, args.repetitions)
        iters = int(km.n_iter_)
        print(f"scikit-learn {__import__('sklearn').__version__} KMeans(lloyd, k-means++, tol 1e-4): "
              f"{ms:.1f} ms wall, {cpu:.1f} ms CPU  (wall runs {', '.join(f'{t:.0f}' for t in times)}; {iters} iterations, "
              f"inertia {km.inertia_:.2f})")
        for niter in (25, iters):
            def faiss_fit(niter=niter):
                km = faiss.Kmeans(x.shape[1], args.k, niter=niter, seed=args.seed, nredo=1,
                                  max_points_per_centroid=x.shape[0], verbose=False)
                km.train(x)
                return km
            ms, times, cpu, fk = median_ms(faiss_fit, args.repetitions)
            print(f"faiss {faiss.__version__} Kmeans(niter={niter}, random init, all points): {ms:.1f} ms wall, {cpu:.1f} ms CPU  "
                  f"(wall runs {', '.join(f'{t:.0f}' for t in times)}; final objective {fk.obj[-1]:.2f})")


if __name__ == "__main__":
    main()
