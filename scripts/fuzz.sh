#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan + libFuzzer) in a build
# directory of their own and runs each for a bounded time, starting from its seed corpus in
# tests/fuzz/corpus/<target>/. Fails when a target crashes, leaks, trips a sanitizer or one of
# its properties, times out on one input or allocates beyond the limit; it then prints the
# command that reruns the saved input.
#   DVPR_FUZZ_SECONDS  seconds per target (default 15: seven targets, about 1.75 minutes)
#   DVPR_FUZZ_BUILD    build directory (default build/fuzz)
#   DVPR_FUZZ_TARGETS  the targets to run (default: all)
#   DVPR_FUZZ_SEED     libFuzzer's seed (default 1, so CI replays the same mutations and a finding
#                      reproduces; 0 lets libFuzzer pick one, to explore further by hand)
# New inputs a run finds go to $DVPR_FUZZ_BUILD/corpus/<target>/ (kept for the next local run,
# never committed); failing inputs to $DVPR_FUZZ_BUILD/findings/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_EACH=${DVPR_FUZZ_SECONDS:-15}
SEED=${DVPR_FUZZ_SEED:-1}
BUILD=${DVPR_FUZZ_BUILD:-build/fuzz}
read -r -a TARGETS <<< "${DVPR_FUZZ_TARGETS:-config npy csv bin poses lcm udpm}"

cmake -S . -B "$BUILD" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDVPR_FUZZ=ON -DDVPR_WERROR=ON \
  -DDVPR_BUILD_TESTS=OFF -DDVPR_BUILD_BENCH=OFF -DDVPR_ARCH=generic >/dev/null
# Only the fuzz targets and the libraries they link (DVPR_ARCH=generic: one variant of each).
cmake --build "$BUILD" -j "$(nproc)" --target dvpr_fuzz

# The data targets write each input to a file: tmpfs when there is one.
if [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1

failed=()
for t in "${TARGETS[@]}"; do
  bin="$BUILD/tests/fuzz/fuzz_$t"
  work="$BUILD/corpus/$t"
  findings="$(pwd)/$BUILD/findings/$t"
  log="$BUILD/logs/fuzz_$t.log"
  mkdir -p "$work" "$findings" "$(dirname "$log")"
  # The first corpus folder receives new inputs, so the committed seeds stay untouched.
  # -timeout: one input running longer than 10 s is a failure (inputs normally take well under
  # 10 ms); -rss_limit_mb also bounds a single allocation (malloc_limit_mb defaults to it).
  set +e
  "$bin" "$work" "tests/fuzz/corpus/$t" -max_total_time="$SECONDS_EACH" -seed="$SEED" -timeout=10 \
    -rss_limit_mb=2048 -error_exitcode=77 -timeout_exitcode=78 -print_final_stats=1 \
    -artifact_prefix="$findings/" >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  if [ "$rc" -eq 0 ]; then
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
