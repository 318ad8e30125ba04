#!/usr/bin/env bash
# The README's demo command: install, build, run the default experiment.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build_release.sh
exec build/release/dvpr run experiments/configs/paper_kitti00.yaml "$@"
