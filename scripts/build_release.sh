#!/usr/bin/env bash
# Optimised build of the dvpr command and the benchmarks into build/release, with the default
# instruction set (DVPR_ARCH=auto: on x86-64 the dispatch pair dvpr + dvpr-x86-64-v3, which runs
# on any x86-64 CPU and fast where AVX2 is: binaries that travel). scripts/demo.sh builds
# only dvpr, for this machine, into build/demo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DDVPR_BUILD_TESTS=OFF >/dev/null
cmake --build build/release -j "$(nproc)"
