#!/usr/bin/env bash
# Optimised build of the dvpr command and the benchmarks into build/release.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DDVPR_BUILD_TESTS=OFF >/dev/null
cmake --build build/release -j "$(nproc)"
