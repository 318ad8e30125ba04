#!/usr/bin/python3
"""Pools replays of several dvpr traces, each replayed several times by ns-3 (csma_replay_ns3,
wifi_replay_ns3 with --RngRun=1..k), so that one run's backoff draws do not decide the comparison.

    /usr/bin/python3 bench/peers/pool_replays.py DIR [--open-loop]

DIR holds one folder per dvpr run (`dvpr run ... --set seed=S --out DIR/sS`), each with dvpr's
messages.csv and the ns-3 replays of each strategy as ns3_<strategy>_<k>.csv. With --open-loop
the dvpr side is not the run itself but dvpr's own open-loop replays of it, dvpr_<strategy>_<k>.csv
(bench/replay_trace.cpp with --seed=k): the same experiment as ns-3's. Per strategy it
prints, averaged over the traces (each trace's ns-3 figures averaged over its replays first),
the mean latency, the p99 (nearest rank) and the dropped share of the rows on each side, and
ns-3 against dvpr; then the per-trace differences of the mean. Standard library only.
"""
import csv
import glob
import math
import sys


def dvpr_rows(path, strategy):
    latencies, rows, dropped = [], 0, 0
    with open(path, newline='') as f:
        for r in csv.DictReader(f):
            if r['strategy'] != strategy:
                continue
            rows += 1
            if r['dropped'] == '1':
                dropped += 1
            elif r['delivered_ns']:
                latencies.append(int(r['delivered_ns']) - int(r['sent_ns']))
    return latencies, rows, dropped


def ns3_rows(path):  # a replay's output (ns-3's, or dvpr's own open loop)
    latencies, rows, dropped = [], 0, 0
    with open(path, newline='') as f:
        for r in csv.DictReader(f):
            rows += 1
            if r['delivered_ns']:
                latencies.append(int(r['delivered_ns']) - int(r['sent_ns']))
            else:
                dropped += 1
    return latencies, rows, dropped


def p99(values):
    s = sorted(values)
    return s[max(0, math.ceil(0.99 * len(s)) - 1)]


def mean(values):
    return sum(values) / len(values)


def main():
    args = [a for a in sys.argv[1:] if a != '--open-loop']
    open_loop = len(args) + 1 < len(sys.argv)
    if len(args) != 1:
        sys.exit(__doc__)
    root = args[0]
    for strategy in ('decentralized', 'broadcast'):
        d_mean, n_mean, d_p99, n_p99, d_drop, n_drop = [], [], [], [], [], []
        for trace in sorted(glob.glob(f'{root}/*/messages.csv')):
            folder = trace[:-len('/messages.csv')]
            replays = [ns3_rows(p) for p in sorted(glob.glob(f'{folder}/ns3_{strategy}_*.csv'))]
            if open_loop:
                own = [ns3_rows(p) for p in sorted(glob.glob(f'{folder}/dvpr_{strategy}_*.csv'))]
            else:
                own = [dvpr_rows(trace, strategy)]
            if not replays or not own or not all(o[0] for o in own):
                continue
            d_mean.append(mean([mean(o[0]) for o in own]))
            d_p99.append(mean([p99(o[0]) for o in own]))
            d_drop.append(mean([o[2] / o[1] for o in own]))
            n_mean.append(mean([mean(r[0]) for r in replays]))
            n_p99.append(mean([p99(r[0]) for r in replays]))
            n_drop.append(mean([r[2] / r[1] for r in replays]))
        if not d_mean:
            continue
        print(f'{strategy}: {len(d_mean)} traces; '
              f'mean latency dvpr {mean(d_mean) / 1e6:.1f} ms, ns-3 {mean(n_mean) / 1e6:.1f} ms '
              f'({100 * (mean(n_mean) / mean(d_mean) - 1):+.2f} %); '
              f'p99 dvpr {mean(d_p99) / 1e6:.1f} ms, ns-3 {mean(n_p99) / 1e6:.1f} ms '
              f'({100 * (mean(n_p99) / mean(d_p99) - 1):+.2f} %); '
              f'dropped dvpr {100 * mean(d_drop):.2f} %, ns-3 {100 * mean(n_drop):.2f} % '
              f'({100 * (mean(n_drop) - mean(d_drop)):+.2f} points)')
        print('  per trace, mean latency ns-3 against dvpr (%):',
              ' '.join(f'{100 * (n / d - 1):+.1f}' for n, d in zip(n_mean, d_mean)))


if __name__ == '__main__':
    main()
