#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz (every fuzz_<name>.cpp with a seed corpus
# tests/fuzz/corpus/<name>/) each for a bounded time. They are built inside the sanitizer test
# build (GCC, ASan + UBSan, -DDVPR_FUZZ=ON: tests/fuzz/fuzz_flags.cmake) from the objects the
# test suite runs, so after scripts/test.sh nothing is left to compile but their links. Fails
# when a target crashes, leaks, trips a sanitizer or one of its properties, times out on one
# input or allocates beyond the limit; it then prints the command that reruns the saved input.
#   DVPR_FUZZ_SECONDS  seconds per target (default 15: seven targets, one per processor at a
#                      time: about a minute on 2 cores)
#   DVPR_FUZZ_BUILD    the sanitizer build directory (default build/asan, scripts/test.sh's)
#   DVPR_FUZZ_TARGETS  the targets to run (default: all)
#   DVPR_FUZZ_SEED     libFuzzer's seed (default 1, so CI replays the same mutations and a finding
#                      reproduces; 0 lets libFuzzer pick one, to explore further by hand)
# New inputs a run finds go to $DVPR_FUZZ_BUILD/fuzz/corpus/<target>/ (kept for the next local
# run, never committed); failing inputs to $DVPR_FUZZ_BUILD/fuzz/findings/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_EACH=${DVPR_FUZZ_SECONDS:-15}
SEED=${DVPR_FUZZ_SEED:-1}
BUILD=${DVPR_FUZZ_BUILD:-build/asan}
# Every fuzz_<name>.cpp with a seed corpus, as tests/fuzz/CMakeLists.txt finds them.
ALL=$(cd tests/fuzz && for f in fuzz_*.cpp; do n=${f#fuzz_}; n=${n%.cpp}; if [ -d "corpus/$n" ]; then echo "$n"; fi; done)
read -r -a TARGETS <<< "${DVPR_FUZZ_TARGETS:-$(echo $ALL)}"

# scripts/test.sh's configuration, plus the fuzz targets.
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DDVPR_SANITIZE=ON -DDVPR_WERROR=ON -DDVPR_BUILD_BENCH=OFF -DDVPR_ARCH=x86-64-v3 -DDVPR_FUZZ=ON >/dev/null
cmake --build "$BUILD" -j "$(nproc)" --target dvpr_fuzz

# The data targets write each input to a file: tmpfs when there is one.
if [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1

# One target per processor at a time (a libFuzzer run is one single-threaded process): seven
# targets of 15 s take about a minute on 2 cores instead of two. Each writes its own log and
# exit status; they are reported in the order of TARGETS once all have finished.
JOBS=$(nproc)
status_dir="$BUILD/fuzz/status"
rm -rf "$status_dir"
mkdir -p "$status_dir"
fuzz_one() {  # fuzz_one TARGET: runs it, leaves its exit status in $status_dir/TARGET
  local t=$1
  local bin="$BUILD/tests/fuzz/fuzz_$t"
  local work="$BUILD/fuzz/corpus/$t"
  local findings
  findings="$(pwd)/$BUILD/fuzz/findings/$t"
  local log="$BUILD/fuzz/logs/fuzz_$t.log"
  mkdir -p "$work" "$findings" "$(dirname "$log")"
  # The first corpus folder receives new inputs, so the committed seeds stay untouched.
  # -timeout: one input running longer than 10 s is a failure (inputs normally take well under
  # 10 ms); -rss_limit_mb also bounds a single allocation (malloc_limit_mb defaults to it).
  local rc=0
  "$bin" "$work" "tests/fuzz/corpus/$t" -max_total_time="$SECONDS_EACH" -seed="$SEED" -timeout=10 \
    -rss_limit_mb=2048 -error_exitcode=77 -timeout_exitcode=78 -print_final_stats=1 \
    -artifact_prefix="$findings/" >"$log" 2>&1 || rc=$?
  echo "$rc" >"$status_dir/$t"
}
running=0
for t in "${TARGETS[@]}"; do
  if [ "$running" -ge "$JOBS" ]; then
    wait -n || true
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
wait

failed=()
for t in "${TARGETS[@]}"; do
  bin="$BUILD/tests/fuzz/fuzz_$t"
  log="$BUILD/fuzz/logs/fuzz_$t.log"
  rc=$(cat "$status_dir/$t" 2>/dev/null || echo "no status")
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" 2>/dev/null | tail -n 1)
  if [ "$rc" = 0 ]; then
    echo "fuzz_$t: ${runs:-?} executions in ${SECONDS_EACH} s, nothing found" >&2
    continue
  fi
  failed+=("$t")
  echo "fuzz_$t: FAILED (exit $rc) after ${runs:-?} executions; the end of $log:" >&2
  grep -v '^#' "$log" | tail -n 40 >&2
  for input in $(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log"); do
    echo "fuzz_$t: rerun the failing input with: $bin $input" >&2
    echo "fuzz_$t: (once fixed, add it to tests/fuzz/corpus/$t/ so every run replays it)" >&2
  done
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: failed: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: ${#TARGETS[@]} targets, nothing found" >&2
