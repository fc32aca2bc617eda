#!/usr/bin/env bash
# One-step set-up and entry points on a fresh Debian 12 machine:
#   bash cmake/bootstrap.sh run [ARGS...]   build, then run the default scene (cosmems run cantilever-haptic)
#   bash cmake/bootstrap.sh test            build, then run the whole test suite with CTest
#   bash cmake/bootstrap.sh bench [NAME [ARGS...]]  build with the benchmarks, then run one
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
# The benchmarks are built by `bench` only: compiling them would take a third of the time `run`
# and `test` need.
configure() {
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCOSMEMS_BUILD_BENCHMARKS="$1" >/dev/null
}

case "${1:-}" in
  run)
    shift
    configure OFF
    cmake --build "$build_dir" -j"$jobs" --target cosmems
    exec "$build_dir/src/cli/cosmems" run cantilever-haptic "$@" ;;
  test)
    configure OFF
    cmake --build "$build_dir" -j"$jobs"
    exec ctest --test-dir "$build_dir" --output-on-failure -j"$jobs" ;;
  bench)
    shift
    configure ON
    cmake --build "$build_dir" -j"$jobs"
    if [ $# -eq 0 ]; then ls "$build_dir/bench"; exit 0; fi
    name=$1; shift
    exec "$build_dir/bench/$name" "$@" ;;
  *) echo "usage: bash cmake/bootstrap.sh run [--json ...] | test | bench [NAME [ARGS...]]" >&2
     exit 2 ;;
esac
