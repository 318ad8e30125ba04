#!/usr/bin/env bash
# The README's test command: install what is missing, build with
# AddressSanitizer + UndefinedBehaviorSanitizer, run the whole suite (with every fuzz target's
# corpus replayed), then fuzz each target for a bounded time (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
BUILD=build/asan
# x86-64-v3 pinned (not the default dispatch, cmake/DvprArch.cmake): the golden files are that
# build's, and the tests' in-process references must compute as the dvpr they run does.
# DVPR_FUZZ=ON: the libFuzzer targets are linked from this build's objects (tests/fuzz), so
# scripts/fuzz.sh below compiles nothing.
# -g1: line tables only, all a sanitizer's or a crash's stack trace names (function, file, line);
# full -g makes the compiler spend about a fifth more on every file (docs/usage.md, "Build time").
JOBS=$(nproc)
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DDVPR_SANITIZE=ON -DDVPR_WERROR=ON -DDVPR_BUILD_BENCH=OFF -DDVPR_ARCH=x86-64-v3 -DDVPR_FUZZ=ON >/dev/null
start=$SECONDS
cmake --build "$BUILD" -j "$JOBS"
echo "test: building took $((SECONDS - start)) s" >&2
start=$SECONDS
ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS" --timeout 600
echo "test: the suite took $((SECONDS - start)) s" >&2
# About 15 s of fuzzing per target.
DVPR_FUZZ_BUILD="$BUILD" bash scripts/fuzz.sh
