#!/usr/bin/env bash
# Installs what Entourage needs to build, run and test, from Debian 12 packages only.
# Idempotent: packages already installed are skipped; `apt-get update` runs at most once.
#   deploy/setup.sh           what building, running and testing need
#   deploy/setup.sh --bench   also what the benchmarks compare with and draw with: SUMO (the peer
#                             simulator of entourage-bench-sumo) and gnuplot (entourage-bench-fd's PNG)
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libfastrtps-dev libfastcdr-dev fastddsgen fastdds-tools
  libeigen3-dev libprotobuf-dev protobuf-compiler
  libspdlog-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  zlib1g-dev procps
)
for arg in "$@"; do
  case "$arg" in
    --bench) packages+=(sumo gnuplot-nox) ;;
    *) echo "setup: unknown option $arg (known: --bench)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  SUDO=sudo
else
  SUDO=
fi
echo "setup: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
