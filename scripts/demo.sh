#!/usr/bin/env bash
# The README's demo command: install what is missing, build the dvpr program (no tests, no
# benchmarks) for this machine's instruction set into build/demo, run the default experiment.
# DVPR_ARCH=host (cmake/DvprArch.cmake): x86-64-v3 where this CPU runs it, generic otherwise;
# the same code and results the dispatch build (scripts/build_release.sh, for binaries that
# travel) runs on this machine, compiled once instead of twice.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh demo
cmake -S . -B build/demo -DCMAKE_BUILD_TYPE=Release -DDVPR_ARCH=host -DDVPR_BUILD_TESTS=OFF \
  -DDVPR_BUILD_BENCH=OFF >/dev/null
cmake --build build/demo -j "$(nproc)" --target dvpr
exec build/demo/dvpr run experiments/configs/paper_kitti00.yaml "$@"
