#!/usr/bin/env bash
# Runs the tests that depend on real time (real agent processes over UDP multicast, timers,
# Open MPI's kill sequence) N times each while LOAD other processes keep every core busy, and
# prints how many of the N passed. They wait on the events they need, so a loaded machine must
# not fail them (README, "Two commands").
#
#   scripts/stress_timing_tests.sh BUILD_DIR [N=50] [LOAD=2] [FIRST=1]
#
# BUILD_DIR is a configured and built tree (scripts/test.sh's build/asan). Exit 1 when any run
# of any test failed; each failing run's output is kept in BUILD_DIR/stress/<test>.<i>.log.
# FIRST numbers the runs FIRST .. FIRST + N - 1, so that a stress run cut short can be continued
# later without overwriting the logs it kept. Never run two instances at once: the tests' own
# temporary folders are named after the test, so two runs of one test would share them.
set -u
build=${1:?usage: scripts/stress_timing_tests.sh BUILD_DIR [N] [LOAD]}
runs=${2:-50}
load=${3:-2}
first=${4:-1}
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

# Round robin: run i of every test, then run i + 1, so that a run cut short has as many runs of
# each test; the counts so far go to stderr after every round.
declare -A pass seconds
all=("${lcm_tests[@]}")
if [[ -f "$build/CTestTestfile.cmake" ]]; then
  for t in "${ctest_tests[@]}"; do
    if ctest --test-dir "$build" -N -R "^$t\$" | grep -q "Total Tests: 1"; then
      all+=("$t")
    else
      echo "stress: $t is not in this build (no Open MPI), skipped" >&2
    fi
  done
fi
run_one() {  # test run-number
  if [[ " ${ctest_tests[*]} " == *" $1 "* ]]; then
    ctest --test-dir "$build" -R "^$1\$" --output-on-failure
  else
    "$binary" --gtest_filter="$1"
  fi
}
for t in "${all[@]}"; do pass[$t]=0; seconds[$t]=0; done
for i in $(seq "$first" $(( first + runs - 1 ))); do
  for t in "${all[@]}"; do
    start=$(date +%s)
    if run_one "$t" > "$logs/$t.$i.log" 2>&1; then
      pass[$t]=$(( ${pass[$t]} + 1 )); rm -f "$logs/$t.$i.log"
    fi
    seconds[$t]=$(( ${seconds[$t]} + $(date +%s) - start ))
  done
  done_runs=$(( i - first + 1 ))
  echo "stress: round $done_runs of $runs (run $i) done, load average $(cut -d' ' -f1-3 /proc/loadavg)" >&2
  for t in "${all[@]}"; do echo "  $t ${pass[$t]} of $done_runs" >&2; done
done
failed=0
for t in "${all[@]}"; do
  printf '%-75s %3d of %d passed  (%d s in all)\n' "$t" "${pass[$t]}" "$runs" "${seconds[$t]}"
  [[ ${pass[$t]} -eq $runs ]] || failed=1
done
exit $failed
