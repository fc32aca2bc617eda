#!/usr/bin/env bash
# One-step set-up and entry points on a fresh Debian 12 machine:
#   bash cmake/bootstrap.sh run [ARGS...]   build, then run the default scene (cosmems run cantilever-haptic)
#   bash cmake/bootstrap.sh test            build, then run the whole test suite with CTest
# Installs the Debian packages the build needs when run as root or with password-less sudo;
# otherwise prints the exact apt-get line and stops. COSMEMS_BUILD_DIR overrides build/release.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake make libeigen3-dev libsuitesparse-dev libgtest-dev libgmock-dev
  libbenchmark-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
  elif sudo -n true 2>/dev/null; then
    sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
  else
    echo "cosmems needs these Debian packages; install them with:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi

build_dir=${COSMEMS_BUILD_DIR:-build/release}
jobs=$(nproc)
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" -j"$jobs"

case "${1:-}" in
  run) shift; exec "$build_dir/src/cli/cosmems" run cantilever-haptic "$@" ;;
  test) exec ctest --test-dir "$build_dir" --output-on-failure -j"$jobs" ;;
  *) echo "usage: bash cmake/bootstrap.sh run [--json ...] | test" >&2; exit 2 ;;
esac
