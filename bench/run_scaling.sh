#!/usr/bin/env bash
# Runs bench_scaling's configurations (frames x robots), each in a process of its own and RUNS
# times, writes the medians to docs/figures/performance_scaling.dat and draws
# docs/figures/performance_scaling.png (gnuplot). Needs a Release build in build/release.
#   bench/run_scaling.sh [RUNS] [FRAMES...]     e.g. bench/run_scaling.sh 3 10000 100000
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
shift || true
frames=("$@")
[ ${#frames[@]} -eq 0 ] && frames=(10000 100000 1000000)
out=docs/figures/performance_scaling.dat
tmp=$(mktemp)
echo "# frames robots wall_s cpu_s peak_rss_MiB (medians of $runs runs, bench_scaling)" > "$out"
for f in "${frames[@]}"; do
  for r in 10 100 1000; do
    : > "$tmp"
    for _ in $(seq "$runs"); do
      (cd build/release/bench && ./bench_scaling --benchmark_filter="BM_Scaling/$f/$r/" \
        --benchmark_format=csv 2>/dev/null) | grep '^"BM_Scaling' >> "$tmp"
    done
    # csv: name,iterations,real_time,cpu_time,time_unit,...,comparisons,events,frames,peak_rss_MiB,robots
    python3 - "$tmp" "$f" "$r" >> "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.reader(open(sys.argv[1])))
med = lambda i: statistics.median(float(r[i]) for r in rows)
print(sys.argv[2], sys.argv[3], med(2), med(3), med(-2))
PY
    tail -1 "$out"
  done
done
rm -f "$tmp"
gnuplot bench/performance_scaling.gp
