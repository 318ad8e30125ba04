#!/usr/bin/env bash
# Runs bench_scaling's configurations (frames x robots), each in a process of its own and RUNS
# times, writes the medians to docs/figures/performance_scaling.dat and draws
# docs/figures/performance_scaling.png (gnuplot). Needs a Release build in build/release
# (cmake -DCMAKE_BUILD_TYPE=Release -DDVPR_ARCH=x86-64-v3 -DDVPR_BUILD_BENCH=ON).
#   bench/run_scaling.sh [RUNS] [FRAMES...]     e.g. bench/run_scaling.sh 3 10000 100000
#   ROBOTS="1000" bench/run_scaling.sh 1 1000000  (team sizes; default 10 100 1000)
#   TRAINING=deployment ...  (the routing centroids from the deployment's own environment,
#                             BM_ScalingDeploymentTrained; default diverse, BM_Scaling)
# Each configuration's line is appended to the .dat as it finishes, so a sweep can be run in
# parts (APPEND=1 keeps the lines already there). The expensive corners (10^6 frames with 10 or
# 100 robots: a few robots store most frames, the search cost grows with their square) take
# hours on two cores; docs/performance.md says which points were measured.
# Transparent huge pages for malloc's heap (the kernel's THP mode here is madvise): a 10^6-frame
# run faults in about 3 GiB, and 4 KiB pages made that a third to a half of its CPU time
# (docs/performance.md). Set GLIBC_TUNABLES yourself to measure without.
export GLIBC_TUNABLES=${GLIBC_TUNABLES-glibc.malloc.hugetlb=1}
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
shift || true
frames=("$@")
[ ${#frames[@]} -eq 0 ] && frames=(10000 100000 1000000)
read -r -a robots <<< "${ROBOTS:-10 100 1000}"
training=${TRAINING:-diverse}
case "$training" in
  diverse) bench=BM_Scaling ;;
  deployment) bench=BM_ScalingDeploymentTrained ;;
  *) echo "run_scaling.sh: TRAINING must be diverse or deployment, got '$training'" >&2; exit 2 ;;
esac
out=docs/figures/performance_scaling.dat
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
if [ "${APPEND:-0}" != 1 ]; then
  echo "# frames robots wall_s cpu_s peak_rss_MiB runs training (medians, bench_scaling)" > "$out"
fi
for f in "${frames[@]}"; do
  for r in "${robots[@]}"; do
    : > "$tmp"
    for _ in $(seq "$runs"); do
      build/release/bench/bench_scaling --benchmark_filter="^$bench/$f/$r/" \
        --benchmark_format=csv 2>/dev/null | grep -E "^(name,|\"$bench/)" >> "$tmp"
    done
    # csv: a header line (name,iterations,real_time,cpu_time,...,peak_rss_MiB,...) per run
    /usr/bin/python3 - "$tmp" "$f" "$r" "$runs" "$training" >> "$out" <<'PY'
import csv, statistics, sys
lines = list(csv.reader(open(sys.argv[1])))
header = next(l for l in lines if l[0] == "name")
rows = [l for l in lines if l[0] != "name"]
col = {name: i for i, name in enumerate(header)}
med = lambda name: statistics.median(float(r[col[name]]) for r in rows)
print(sys.argv[2], sys.argv[3], med("real_time"), med("cpu_time"), med("peak_rss_MiB"), sys.argv[4], sys.argv[5])
PY
    tail -1 "$out"
  done
done
gnuplot bench/performance_scaling.gp
