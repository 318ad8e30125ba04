#!/usr/bin/python3
"""Compares one run of a dvpr messages.csv with its ns-3 replay (csma_replay_ns3, wifi_replay_ns3).

    /usr/bin/python3 bench/peers/compare_replay.py DVPR_MESSAGES.csv NS3_OUT.csv \
        [--protocol P] [--strategy S] [--robots N] [--run R] [--variant V]

The run filter is the replay's: an option left out takes the first data row's value. For each
side it prints the rows, the delivered share, the mean and p99 (nearest-rank) latency over the
delivered rows (latency = delivered_ns - sent_ns) and the dropped share of the rows; then the
relative differences (ns-3 against dvpr: mean and p99 in %, drops in percentage points of the
rows), a row-by-row comparison and the same figures by message role. On the dvpr side a row is
dropped when its `dropped` column is 1; a row neither delivered nor dropped was still in flight
when the run ended and is counted apart. On the ns-3 side every row without delivered_ns is
dropped (the replay runs until nothing is left in flight). Standard library only.
"""
import argparse
import csv
import math
import sys

KEYS = ("protocol", "strategy", "robots", "run", "network_variant")


def read_dvpr(path, want):
    rows = []
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        chosen = None
        for r in reader:
            if chosen is None:
                chosen = {k: (want[k] if want[k] is not None else r.get(k, "")) for k in KEYS}
            if any(r.get(k, "") != chosen[k] for k in KEYS):
                continue
            rows.append(r)
    if not rows:
        sys.exit(f"{path}: no rows for the chosen run")
    return chosen, rows


def read_ns3(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def latencies(rows):
    return [int(r["delivered_ns"]) - int(r["sent_ns"]) for r in rows if r["delivered_ns"] != ""]


def p99(values):
    if not values:
        return math.nan
    s = sorted(values)
    return s[max(math.ceil(0.99 * len(s)), 1) - 1]


def mean(values):
    return sum(values) / len(values) if values else math.nan


def stats(rows, dropped):
    lat = latencies(rows)
    n = len(rows)
    return {
        "rows": n,
        "delivered": len(lat),
        "delivered_share": len(lat) / n if n else math.nan,
        "mean_ms": mean(lat) / 1e6,
        "p99_ms": p99(lat) / 1e6,
        "dropped_share": dropped / n if n else math.nan,
    }


def rel(a, b):
    return (b - a) / a * 100 if a else math.nan


def line(name, s, extra=""):
    print(f"{name:6} rows {s['rows']:>8}  delivered {100 * s['delivered_share']:8.3f} %  "
          f"mean {s['mean_ms']:10.4f} ms  p99 {s['p99_ms']:10.4f} ms  "
          f"dropped {100 * s['dropped_share']:7.3f} %{extra}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dvpr_messages")
    ap.add_argument("ns3_output")
    for k in ("protocol", "strategy", "robots", "run"):
        ap.add_argument("--" + k)
    ap.add_argument("--variant", dest="network_variant")
    a = ap.parse_args()
    want = {k: getattr(a, k) for k in KEYS}
    chosen, dv = read_dvpr(a.dvpr_messages, want)
    ns = read_ns3(a.ns3_output)
    print("run: " + " ".join(f"{k}={v}" for k, v in chosen.items()))
    if len(ns) != len(dv):
        sys.exit(f"{a.ns3_output}: {len(ns)} rows, the dvpr run has {len(dv)}: not the same run?")
    for i, (d, n) in enumerate(zip(dv, ns)):
        if (d["sent_ns"], d["src"], d["dst"], d["channel"]) != (n["sent_ns"], n["src"], n["dst"], n["channel"]):
            sys.exit(f"row {i + 1}: dvpr {d['sent_ns']},{d['src']},{d['dst']},{d['channel']} vs ns-3 "
                     f"{n['sent_ns']},{n['src']},{n['dst']},{n['channel']}: not the same run?")

    dv_dropped = sum(1 for r in dv if r.get("dropped", "0") == "1")
    dv_inflight = sum(1 for r in dv if r["delivered_ns"] == "" and r.get("dropped", "0") != "1")
    ns_dropped = sum(1 for r in ns if r["delivered_ns"] == "")
    sd, sn = stats(dv, dv_dropped), stats(ns, ns_dropped)
    line("dvpr", sd, f"  (in flight at the end {dv_inflight})" if dv_inflight else "")
    line("ns-3", sn)
    print(f"ns-3 vs dvpr: mean {rel(sd['mean_ms'], sn['mean_ms']):+.2f} %, p99 {rel(sd['p99_ms'], sn['p99_ms']):+.2f} %, "
          f"drops {100 * (sn['dropped_share'] - sd['dropped_share']):+.3f} pp of the rows")

    both = [(int(d["delivered_ns"]) - int(n["delivered_ns"])) for d, n in zip(dv, ns)
            if d["delivered_ns"] != "" and n["delivered_ns"] != ""]
    if both:
        same = sum(1 for x in both if x == 0)
        print(f"rows delivered on both sides {len(both)}: same arrival to the ns {same} "
              f"({100 * same / len(both):.2f} %), within 1 us "
              f"{sum(1 for x in both if abs(x) <= 1000)}, mean |ns-3 - dvpr| "
              f"{mean([abs(x) for x in both]) / 1e6:.4f} ms, mean ns-3 - dvpr {-mean(both) / 1e6:+.4f} ms")
    only_dv = sum(1 for d, n in zip(dv, ns) if d["delivered_ns"] != "" and n["delivered_ns"] == "")
    only_ns = sum(1 for d, n in zip(dv, ns) if d["delivered_ns"] == "" and n["delivered_ns"] != "")
    print(f"delivered by dvpr only {only_dv}, by ns-3 only {only_ns}")

    roles = sorted({d.get("role", "") for d in dv})
    if len(roles) > 1 or roles != [""]:
        print("by role:")
        for role in roles:
            idx = [i for i, d in enumerate(dv) if d.get("role", "") == role]
            rd = [dv[i] for i in idx]
            rn = [ns[i] for i in idx]
            a_ = stats(rd, sum(1 for r in rd if r.get("dropped", "0") == "1"))
            b_ = stats(rn, sum(1 for r in rn if r["delivered_ns"] == ""))
            print(f"  {role:15} rows {a_['rows']:>7}  mean dvpr {a_['mean_ms']:9.4f} ns-3 {b_['mean_ms']:9.4f} ms  "
                  f"p99 dvpr {a_['p99_ms']:9.4f} ns-3 {b_['p99_ms']:9.4f} ms  "
                  f"dropped dvpr {100 * a_['dropped_share']:6.2f} ns-3 {100 * b_['dropped_share']:6.2f} %")


if __name__ == "__main__":
    main()
