#!/usr/bin/env bash
# CI's check of what users build and run (.ci/run, after scripts/test.sh): the default Release
# configuration (DVPR_ARCH=auto: on x86-64 the dispatch pair `dvpr` + `dvpr-x86-64-v3`, as
# scripts/build_release.sh makes it; no tests, no benchmarks) built in a folder of its own, then
# a small sweep of the default experiment (2 and 3 robots, 1 run) with each variant: exit 0, the
# result files, and `dvpr --version` naming the code that runs.
#   DVPR_SMOKE_BUILD       build directory (default build/release-smoke)
#   DVPR_SMOKE_BUILD_ONLY  1: build and stop (.ci/run builds it beside the test command, then
#                          runs this script again for the sweep, which then compiles nothing)
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD=${DVPR_SMOKE_BUILD:-build/release-smoke}
# As a user configures it: warnings are errors in the sanitizer build (scripts/test.sh), not here
# (GCC 12 at -O3 reports false positives, CMakeLists.txt).
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DDVPR_BUILD_TESTS=OFF -DDVPR_BUILD_BENCH=OFF >/dev/null
cmake --build "$BUILD" -j "$(nproc)" --target dvpr
if [ "${DVPR_SMOKE_BUILD_ONLY:-0}" = 1 ]; then
  exit 0
fi

fail() { echo "release smoke: $*" >&2; exit 1; }

# Which variant runs: the generic `dvpr` hands over to dvpr-x86-64-v3 where the CPU runs it.
expected=x86-64
if [ -x "$BUILD/dvpr-x86-64-v3" ]; then
  "$BUILD/dvpr-x86-64-v3" --version >/dev/null 2>&1 && expected=x86-64-v3  # SIGILL: an older CPU
fi
case "$(uname -m)" in x86_64) ;; *) expected=$(uname -m) ;; esac

check_run() {  # check_run LABEL ARCH_SEEN ENV...
  local label=$1 want=$2; shift 2
  local out="$BUILD/smoke/$label"
  rm -rf "$out"
  local version
  version=$(env "$@" "$BUILD/dvpr" --version) || fail "$label: dvpr --version failed"
  case "$version" in *"($want)"*) ;; *) fail "$label: dvpr --version says '$version', expected ($want)" ;; esac
  env "$@" "$BUILD/dvpr" run experiments/configs/paper_kitti00.yaml --quiet --set runs=1 \
    --set 'robots=[2, 3]' --out "$out" >"$BUILD/smoke/$label.stdout" ||
    fail "$label: dvpr run exited with $? (stdout: $BUILD/smoke/$label.stdout)"
  for f in config.yaml runs.csv per_robot.csv summary.json; do
    [ -s "$out/$f" ] || fail "$label: $out/$f missing or empty"
  done
  # One row per protocol, strategy, network, team size and run: at least 2 team sizes.
  rows=$(($(wc -l <"$out/runs.csv") - 1))
  [ "$rows" -ge 2 ] || fail "$label: runs.csv has $rows rows"
  grep -q "results in" "$BUILD/smoke/$label.stdout" || fail "$label: no summary printed"
  echo "release smoke: $label: $version, $rows rows in $out" >&2
}

mkdir -p "$BUILD/smoke"
check_run default "$expected"
if [ "$expected" = x86-64-v3 ]; then
  check_run generic x86-64 DVPR_ARCH=generic
fi
