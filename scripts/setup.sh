#!/usr/bin/env bash
# Installs the Debian 12 packages dvpr needs, skipping those already installed.
# Needs root (or sudo) only when something is missing.
set -euo pipefail

PACKAGES=(
  cmake g++ make pkg-config
  liblcm-dev liblcm-bin libglib2.0-dev       # LCM, lcm-gen, lcm-logplayer, lcm-spy
  libeigen3-dev libboost-dev libyaml-cpp-dev
  libssl-dev                                 # OpenSSL: HMAC-SHA-256 tags of a launched team's messages
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  libgtest-dev libbenchmark-dev
  libclang-rt-14-dev                         # libFuzzer's archive (scripts/fuzz.sh links it with g++)
  gnuplot-nox                                # figures
  python3 python3-numpy                      # independent cross-checks in the tests
  iproute2                                   # ip: loopback multicast for the LCM team tests
  openmpi-bin libopenmpi-dev                 # mpirun -n K dvpr run (optional; CI tests it)
  chromium                                   # headless browser: the replay page's test (tests/replay)
  liblcm-java default-jdk-headless           # lcm.jar and javac: the Java types (dvpr_lcmtypes.jar)
  libjchart2d-java                           # jchart2d.jar, which lcm-spy needs (README "LCM tools")
  python3-matplotlib                         # scripts/examples/bytes_per_channel.py
)

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
