#!/usr/bin/env python3
"""The replay page in a real browser: headless Chromium opens what `dvpr replay` wrote at a chosen
instant (#t=...) and this test compares what the page shows there (its state table: robot
positions, messages in flight, bytes sent so far) with values computed here, independently, from
messages.csv, runs.csv and the KITTI pose file.

Usage: browser_test.py DVPR SOURCE_DIR WORK_DIR
Exit 0 pass, 1 fail, 77 skipped (no chromium: scripts/setup.sh installs it).
"""
import csv
import html.parser
import os
import pathlib
import shutil
import subprocess
import sys

DVPR, SOURCE, WORK = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
CONFIG = SOURCE / "tests" / "replay" / "replay_test.yaml"
ROBOTS, FRAMES, FPS, RANGE_M = 3, 600, 10, 150.0  # as in replay_test.yaml
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def role(channel):  # agents/messages/channels.h and agents/recluster/recluster_messages.h, by hand
    for prefix, name in (("DVPR_QUERY_", "query"), ("DVPR_PROBE_", "query"), ("DVPR_STORE_", "query"),
                         ("DVPR_MATCH_", "reply"), ("DVPR_VREQ_", "verify request"),
                         ("DVPR_VRES_", "verify result"), ("DVPR_SAMPLE_", "re-clustering"),
                         ("DVPR_MIGRATE_", "re-clustering")):
        if channel.startswith(prefix):
            return name
    return "re-clustering" if channel == "DVPR_TABLE" else "other"


def tracks():
    """Each robot's (x, z) per frame: the first FRAMES poses split into ROBOTS contiguous parts."""
    rows = [list(map(float, line.split())) for line in open(SOURCE / "data/kitti/00_poses.txt")][:FRAMES]
    xz = [(r[3], r[11]) for r in rows]
    return [xz[r * FRAMES // ROBOTS:(r + 1) * FRAMES // ROBOTS] for r in range(ROBOTS)]


def position(track, t_us):
    k = t_us * FPS / 1e6
    i = int(k)
    if i >= len(track) - 1:
        return track[-1]
    f = k - i
    return tuple(a + f * (b - a) for a, b in zip(track[i], track[i + 1]))


def in_flight(rows, t_ns):
    out = set()
    for r in rows:
        sent = int(r["sent_ns"])
        arrived = int(r["delivered_ns"]) if r["delivered_ns"] else None
        flying = sent <= t_ns and (t_ns < arrived if arrived is not None else r["dropped"] == "0")
        if flying:
            out.add((r["strategy"], int(r["src"]), int(r["dst"]), role(r["channel"]), (sent + 500) // 1000))
    return out


def in_range(a, b, t_us):
    pa, pb = position(tracks()[a], t_us), position(tracks()[b], t_us)
    return ((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2) ** 0.5 <= RANGE_M


def relays(src, dst, hops, t_us):
    """The robots between src and dst on a shortest path of who hears whom at t (breadth first,
    the lowest id first), as the page should draw a copy of `hops` hops; "" when none fits."""
    came, queue = {src: src}, [src]
    for u in queue:
        for v in range(ROBOTS):
            if v not in came and in_range(u, v, t_us):
                came[v] = u
                queue.append(v)
    if dst not in came or hops <= 1:
        return ""
    path = [dst]
    while path[0] != src:
        path.insert(0, came[path[0]])
    return " ".join(map(str, path[1:-1])) if len(path) - 1 == hops else ""


def check_radio(chromium, rows, page, label):
    """Mid-run on the radio: the pairs in range and, for every copy in flight, its relays."""
    relayed = sorted({(int(r["sent_ns"]) + 500) // 1000 for r in rows if r["hops"] == "2" and r["delivered_ns"]})
    t_us = next(t + 1500 for t in relayed if t > 5e6 and quiet_instant(rows, t + 1500))
    shown = open_page(chromium, page, t_us)
    radio = [r for r in shown if r.get("kind") == "radio"]
    pairs = sum(in_range(a, b, t_us) for a in range(ROBOTS) for b in range(a + 1, ROBOTS))
    check(len(radio) == 1 and float(radio[0]["range-m"]) == RANGE_M and int(radio[0]["pairs-in-range"]) == pairs,
          f"{label}: radio shown {radio}, expected range {RANGE_M} m and {pairs} pairs in range")
    flying = [m for m in shown if m.get("kind") == "message"]
    two_hops = 0
    for m in flying:
        hops = int(m["hops"])
        sent_us = int(m["sent-us"])
        want = relays(int(m["src"]), int(m["dst"]), hops, sent_us)
        check(m["via"] == want, f"{label}: {m['src']}>{m['dst']} sent at {sent_us} us, {hops} hops, "
                                f"drawn via '{m['via']}', expected '{want}'")
        two_hops += hops == 2 and want != ""
    check(two_hops > 0, f"{label}: no relayed copy in flight at {t_us} us: {flying}")
    print(f"{label}: t = {t_us} us, {pairs} pairs in range, {len(flying)} in flight, {two_hops} drawn through a relay")


def bytes_sent(rows, t_ns, shared_medium):
    """Wire bytes sent by t; on a shared medium the copies of one broadcast are one transmission."""
    total, seen = {}, set()
    for r in rows:
        key = (r["strategy"], r["src"], r["sent_ns"], r["channel"])
        if int(r["sent_ns"]) > t_ns or (shared_medium and key in seen):
            continue
        seen.add(key)
        total[r["strategy"]] = total.get(r["strategy"], 0) + int(r["wire_bytes"])
    return total


class StateTable(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.rows, self.inside = [], False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "table" and a.get("id") == "state":
            self.inside = True
        elif tag == "tr" and self.inside:
            self.rows.append({k[5:]: v for k, v in a.items() if k.startswith("data-")})

    def handle_endtag(self, tag):
        if tag == "table":
            self.inside = False


def open_page(chromium, page, t_us):
    url = page.resolve().as_uri() + "#t=%d.%06d" % divmod(t_us, 1000000)
    cmd = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-extensions",
           "--user-data-dir=" + str(WORK / "chromium-profile"), "--virtual-time-budget=5000", "--dump-dom", url]
    dom = subprocess.run(cmd, capture_output=True, text=True, timeout=240, check=True).stdout  # stderr: dbus noise
    table = StateTable()
    table.feed(dom)
    check(table.rows, f"{url}: no state table in the DOM")
    return table.rows


def quiet_instant(rows, t_us):
    """No send or delivery within 2 us of t, so the page's microseconds cannot round across it."""
    t_ns = t_us * 1000
    return all(abs(int(r[c]) - t_ns) > 2000 for r in rows for c in ("sent_ns", "delivered_ns") if r[c])


def busy_instant(rows):
    """Mid-run, a few ms after a verification request was sent and away from a frame time (so the
    robots are between two poses): the request and, on both strategies, other messages fly."""
    vreq = sorted({(int(r["sent_ns"]) + 500) // 1000 for r in rows if role(r["channel"]) == "verify request"})
    candidates = [t + d for t in vreq if 5e6 < t < 15e6 for d in (1500, 5000, 10000, 15000)]
    between = [t for t in candidates if 0.15 <= (t * FPS / 1e6) % 1 <= 0.85 and quiet_instant(rows, t)]

    def shown(t):
        flying = in_flight(rows, t * 1000)
        return (len({m[0] for m in flying}), "verify request" in {m[3] for m in flying}, len(flying), -t)
    return max(between, key=shown)


def check_page(chromium, rows, page, t_us, label, shared_medium, runs_total=None):
    shown = open_page(chromium, page, t_us)
    robots = {int(r["robot"]): (float(r["x"]), float(r["z"])) for r in shown if r.get("kind") == "robot"}
    check(sorted(robots) == list(range(ROBOTS)), f"{label}: robots shown {sorted(robots)}")
    for r, track in enumerate(tracks()):
        want = position(track, t_us)
        got = robots.get(r, (float("nan"), float("nan")))
        # the page keeps decimetres: each coordinate within 0.05 m (+ printing)
        check(all(abs(g - w) <= 0.051 for g, w in zip(got, want)), f"{label}: robot {r} at {got}, expected {want}")
    flying = {(m["strategy"], int(m["src"]), int(m["dst"]), m["role"], int(m["sent-us"]))
              for m in shown if m.get("kind") == "message"}
    want = in_flight(rows, t_us * 1000)
    check(flying == want, f"{label}: in flight shown {sorted(flying)}, expected {sorted(want)}")
    sent = {b["strategy"]: int(float(b["bytes"])) for b in shown if b.get("kind") == "bytes"}
    check(sent == bytes_sent(rows, t_us * 1000, shared_medium), f"{label}: bytes shown {sent}")
    if runs_total is not None:
        check(sent == runs_total, f"{label}: bytes at the end {sent}, runs.csv wire_bytes {runs_total}")
    print(f"{label}: t = {t_us} us, {len(robots)} robots, {len(flying)} messages in flight "
          f"({', '.join(sorted({m[3] for m in flying})) or 'none'}), bytes {sent}")
    return want


def main():
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("SKIP: chromium is not installed (scripts/setup.sh installs Debian's chromium)")
        return 77
    shutil.rmtree(WORK, ignore_errors=True)
    WORK.mkdir(parents=True)
    out = WORK / "result"
    subprocess.run([DVPR, "run", str(CONFIG), "--quiet", "--out", str(out)], check=True, stdout=subprocess.DEVNULL)
    messages = list(csv.DictReader(open(out / "messages.csv")))
    runs = list(csv.DictReader(open(out / "runs.csv")))
    for variant in ("0", "1", "2"):
        subprocess.run([DVPR, "replay", str(out), "--network", variant, "--out", str(WORK / f"net{variant}.html")],
                       check=True, stdout=subprocess.DEVNULL)
    p2p = [r for r in messages if r["network_variant"] == "0"]
    t_us = busy_instant(p2p)
    want = check_page(chromium, p2p, WORK / "net0.html", t_us, "point-to-point, mid-run", False)
    check("verify request" in {m[3] for m in want} and {m[0] for m in want} == {"decentralized", "broadcast"},
          f"the chosen instant shows too little: {sorted(want)}")
    shared = [r for r in messages if r["network_variant"] == "1"]
    end_us = max(int(r["delivered_ns"] or r["sent_ns"]) for r in shared) // 1000 + 1000
    totals = {r["strategy"]: int(r["wire_bytes"]) for r in runs if r["network_variant"] == "1"}
    check_page(chromium, shared, WORK / "net1.html", end_us, "shared medium, after the end", True, totals)
    radio = [r for r in messages if r["network_variant"] == "2"]
    check_radio(chromium, radio, WORK / "net2.html", "radio 150 m, mid-run")
    print("FAILED" if failures else "OK")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
