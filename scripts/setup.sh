#!/usr/bin/env bash
# Installs the Debian 12 packages dvpr needs, skipping those already installed.
#   bash scripts/setup.sh demo   what scripts/demo.sh needs: configure and build the dvpr program
#                                (-DDVPR_BUILD_TESTS=OFF -DDVPR_BUILD_BENCH=OFF) and run the
#                                default experiment with its figures
#   bash scripts/setup.sh [all]  everything: also the tests, benchmarks, fuzzers and optional
#                                tools (scripts/test.sh, scripts/build_release.sh, .ci/run)
# Needs root (or sudo) only when something is missing.
set -euo pipefail

# The REQUIRED packages of CMakeLists.txt's configure step, and gnuplot, which dvpr runs to draw
# the figures. Open MPI and a JDK are optional there (the build says what it leaves out).
DEMO=(
  cmake g++ make pkg-config
  liblcm-dev liblcm-bin libglib2.0-dev       # LCM, lcm-gen, lcm-logplayer, lcm-spy; lcm.pc requires glib-2.0
  libeigen3-dev libboost-dev libyaml-cpp-dev
  libssl-dev                                 # OpenSSL: HMAC-SHA-256 tags of a launched team's messages
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev  # REQUIRED by cmake/FindOpenCVParts.cmake
  gnuplot-nox                                # figures
)
# The tests, the benchmarks, the fuzzers and the optional tools.
REST=(
  libgtest-dev libbenchmark-dev
  libclang-rt-14-dev                         # libFuzzer's archive (scripts/fuzz.sh links it with g++)
  python3 python3-numpy                      # independent cross-checks in the tests
  iproute2                                   # ip: loopback multicast for the LCM team tests
  openmpi-bin libopenmpi-dev                 # mpirun -n K dvpr run (optional; CI tests it)
  chromium                                   # headless browser: the replay page's test (tests/replay)
  liblcm-java default-jdk-headless           # lcm.jar and javac: the Java types (dvpr_lcmtypes.jar)
  libjchart2d-java                           # jchart2d.jar, which lcm-spy needs (README "LCM tools")
  python3-matplotlib                         # scripts/examples/bytes_per_channel.py
)

case "${1:-all}" in
  demo) PACKAGES=("${DEMO[@]}") ;;
  all) PACKAGES=("${DEMO[@]}" "${REST[@]}") ;;
  *) echo "setup: unknown set '$1' (demo, or all: the default)" >&2; exit 2 ;;
esac

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present" >&2
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
