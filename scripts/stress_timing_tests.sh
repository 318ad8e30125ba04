#!/usr/bin/env bash
# Runs the tests that depend on real time (real agent processes over UDP multicast, timers,
# Open MPI's kill sequence) N times each while LOAD other processes keep every core busy, and
# prints how many of the N passed. They wait on the events they need, so a loaded machine must
# not fail them (README, "Two commands").
#
#   scripts/stress_timing_tests.sh BUILD_DIR [N=50] [LOAD=2]
#
# BUILD_DIR is a configured and built tree (scripts/test.sh's build/asan). Exit 1 when any run
# of any test failed; each failing run's output is kept in BUILD_DIR/stress/<test>.<i>.log.
set -u
build=${1:?usage: scripts/stress_timing_tests.sh BUILD_DIR [N] [LOAD]}
runs=${2:-50}
load=${3:-2}
lcm_tests=(
  LcmTransportTest.DeliversCountsGarbageAndKeepsTimersOnSchedule
  LcmTransportTest.UtimeIsTheEpochPlusAgentTimeOverSpeedup
  LcmTeamTest.LaunchedTeamMatchesTheIdealSimulation
  LcmTeamTest.LaunchedBowTeamMatchesTheIdealSimulation
  LcmTeamTest.KilledAgentDoesNotHangTheOthers
  LcmTeamTest.KilledAgentsClustersAreServedByItsSuccessorAfterDetection
  LcmTeamTest.GarbageOnEveryChannelIsCountedAndIgnored
)
ctest_tests=(MpiSweepTest.KilledRankEndsTheJobAndNothingWritten)

binary="$build/tests/test_protocols_lcm"
[[ -x "$binary" ]] || { echo "stress: error: $binary is missing (build the tests first)" >&2; exit 2; }
logs="$build/stress"
mkdir -p "$logs"

busy=()
for _ in $(seq "$load"); do
  sh -c 'while :; do :; done' &
  busy+=($!)
done
trap 'kill "${busy[@]}" 2>/dev/null' EXIT
echo "stress: $load busy loops (pids ${busy[*]}), $(nproc) cores, $runs runs per test" >&2

failed=0
report() {  # name passes seconds
  printf '%-75s %3d of %d passed  (%d s)\n' "$1" "$2" "$runs" "$3"
  [[ $2 -eq $runs ]] || failed=1
}
for t in "${lcm_tests[@]}"; do
  pass=0
  start=$(date +%s)
  for i in $(seq "$runs"); do
    if "$binary" --gtest_filter="$t" > "$logs/$t.$i.log" 2>&1; then
      pass=$((pass + 1)); rm -f "$logs/$t.$i.log"
    fi
  done
  report "$t" "$pass" "$(( $(date +%s) - start ))"
done
if [[ -f "$build/CTestTestfile.cmake" ]]; then
  for t in "${ctest_tests[@]}"; do
    if ! ctest --test-dir "$build" -N -R "^$t\$" | grep -q "Total Tests: 1"; then
      echo "$t: not in this build (no Open MPI), skipped"
      continue
    fi
    pass=0
    start=$(date +%s)
    for i in $(seq "$runs"); do
      if ctest --test-dir "$build" -R "^$t\$" --output-on-failure > "$logs/$t.$i.log" 2>&1; then
        pass=$((pass + 1)); rm -f "$logs/$t.$i.log"
      fi
    done
    report "$t" "$pass" "$(( $(date +%s) - start ))"
  done
fi
exit $failed
