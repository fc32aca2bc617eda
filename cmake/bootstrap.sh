#!/usr/bin/env bash
# One-step set-up and entry points on a fresh Debian 12 machine:
#   bash cmake/bootstrap.sh run [ARGS...]   build, then run the default scene (cosmems run cantilever-haptic)
#   bash cmake/bootstrap.sh test            build, then run the whole test suite with CTest
#   bash cmake/bootstrap.sh python [ARGS...]  build the Python module, then run Debian's python3
#                                     with it on the path (python -c "import cosmems")
#   bash cmake/bootstrap.sh bench [NAME [ARGS...]]  build with the benchmarks on, then run one
#   bash cmake/bootstrap.sh sanitize        the test suite under AddressSanitizer + UBSan, asserts on
#   bash cmake/bootstrap.sh fuzz [SECONDS]  fuzz the scene reader and the trajectory reader (clang)
#   bash cmake/bootstrap.sh report [OUTDIR [ARGS...]]  the accuracy-versus-time report: CSV,
#                                     Markdown and plots in OUTDIR (default build/release/accuracy_report)
#   bash cmake/bootstrap.sh docs            the API reference by Doxygen (build/release/doc/api/html);
#                                     any Doxygen warning fails it
# Installs the Debian packages the build needs when run as root or with password-less sudo;
# otherwise prints the exact apt-get line and stops. COSMEMS_BUILD_DIR overrides build/release.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ ccache cmake make libeigen3-dev libsuitesparse-dev libgtest-dev libgmock-dev
  libbenchmark-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev)
# The viewer (GLFW, OpenGL, Dear ImGui with its back ends, stb for PNG) and its headless test
# (a virtual X server and Mesa's software renderer).
packages+=(pkg-config libglfw3-dev libgl-dev libimgui-dev libstb-dev xvfb xauth libgl1-mesa-dri
  libglx-mesa0)
# The sweep's MPI ranks (Debian's OpenMPI; `mpirun -n N cosmems sweep ...`).
packages+=(openmpi-bin libopenmpi-dev)
# clang and its runtime libraries (the sanitizers' and libFuzzer): the sanitized suite and the
# fuzzers are built with it.
case "${1:-}" in fuzz | sanitize) packages+=(clang libclang-rt-14-dev) ;; esac
# The sweeps' plots and the accuracy report's are drawn by gnuplot.
packages+=(gnuplot-nox)
# The Python module (pybind11) and its tests and example: Debian's interpreter with numpy, scipy,
# pytest and matplotlib.
packages+=(python3-dev pybind11-dev python3-numpy python3-scipy python3-pytest python3-matplotlib)
# The API reference needs Doxygen; only `docs` does.
if [ "${1:-}" = docs ]; then packages+=(doxygen); fi
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
  python)
    # Debian's interpreter with the built package on its path: python -c "import cosmems".
    shift
    configure OFF
    cmake --build "$build_dir" -j"$jobs" --target cosmems_python cosmems
    PYTHONPATH="$(cd "$build_dir" && pwd)/python${PYTHONPATH:+:$PYTHONPATH}" exec /usr/bin/python3 "$@" ;;
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
  sanitize | fuzz)
    # One clang build in build/asan serves both. `sanitize`: the whole test suite under
    # AddressSanitizer + UndefinedBehaviorSanitizer, float-to-integer overflow included, with
    # assertions on: -O1 and no NDEBUG, so the library's and Eigen's asserts run; line tables
    # only (-g1), which is all a report's stack needs and compiles in 60 % of -g's time. Built by
    # clang, which compiles these units in about half of GCC's time at the same flags
    # (doc/testing.md), so the suite also meets a second compiler; the main build stays GCC's.
    # Left out, each for its reason: the malloc-counting tests (the sanitizer owns malloc), the
    # ThreadSanitizer tests (one sanitizer a build; they run in `test`), the viewer's headless
    # run (Mesa's software renderer, not ours, under LeakSanitizer) and the sweep under mpirun
    # (OpenMPI's start-up, likewise). `fuzz [SECONDS]`: each fuzzer for SECONDS, the scene reader
    # and --set up to the built model, and the CSV trajectory reader up to the forces a scripted
    # device sends. The libraries they exercise carry libFuzzer's coverage instrumentation in the
    # same build (tests/fuzz), so the fuzzers link what the sanitized suite already compiled
    # instead of a build of their own (doc/testing.md, "What CI costs").
    asan_dir=${COSMEMS_ASAN_DIR:-build/asan}
    # A folder another compiler configured starts afresh: CMake would reset the cache for the new
    # compiler and drop the options below with it.
    if [ -f "$asan_dir/CMakeCache.txt" ] &&
      ! grep -q '^CMAKE_CXX_COMPILER:.*clang++$' "$asan_dir/CMakeCache.txt"; then
      rm -rf "$asan_dir"
    fi
    cmake -S . -B "$asan_dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
      -DCOSMEMS_SANITIZE=address,undefined,float-cast-overflow \
      -DCOSMEMS_BUILD_FUZZERS=ON -DCOSMEMS_BUILD_BENCHMARKS=OFF -DCOSMEMS_BUILD_EXAMPLES=OFF >/dev/null
    if [ "$1" = sanitize ]; then
      cmake --build "$asan_dir" -j"$jobs" --target cosmems_unit_tests scene_fuzzer trajectory_fuzzer
      exec ctest --test-dir "$asan_dir" --output-on-failure -j"$jobs" -L unit
    fi
    seconds=${2:-60}
    cmake --build "$asan_dir" -j"$jobs" --target scene_fuzzer trajectory_fuzzer
    # New inputs go to the first (scratch) corpus; the kept inputs seed it. A failing input is
    # written to $asan_dir/<fuzzer>-crash-* and belongs in the fuzzer's regressions folder, which
    # the ordinary suite replays.
    for fuzzer in scene trajectory; do
      case $fuzzer in
        scene) kept=(src/scene/scenes tests/fuzz/seeds tests/fuzz/regressions); dict=(-dict=tests/fuzz/scene.dict) ;;
        trajectory) kept=(tests/fuzz/trajectory_seeds tests/fuzz/trajectory_regressions); dict=() ;;
      esac
      mkdir -p "$asan_dir/corpus-$fuzzer"
      # libFuzzer reports every new input it finds: that goes to a log, and only a failure's
      # report and the final figures are printed.
      if ! "$asan_dir/tests/fuzz/${fuzzer}_fuzzer" -max_total_time="$seconds" -timeout=10 \
        -rss_limit_mb=2048 -print_final_stats=1 "${dict[@]}" \
        -artifact_prefix="$asan_dir/$fuzzer-" "$asan_dir/corpus-$fuzzer" "${kept[@]}" \
        > "$asan_dir/$fuzzer.log" 2>&1; then
        tail -n 80 "$asan_dir/$fuzzer.log" >&2
        exit 1
      fi
      echo "$fuzzer fuzzer:"
      grep -E '^(Done|stat::)' "$asan_dir/$fuzzer.log"
    done ;;
  report)
    shift
    out=${1:-$build_dir/accuracy_report}
    if [ $# -gt 0 ]; then shift; fi
    configure ON
    cmake --build "$build_dir" -j"$jobs" --target accuracy_cost_bench
    COSMEMS_BUILD_DIR="$build_dir" exec bash bench/accuracy_cost_report.sh "$out" "$@" ;;
  docs)
    # Doxygen only, no compiler: the target runs doxygen over include/ and fails on a warning.
    configure OFF
    cmake --build "$build_dir" --target cosmems_doxygen
    echo "API reference: $build_dir/doc/api/html/index.html" ;;
  *) echo "usage: bash cmake/bootstrap.sh run [--json ...] | test | python [ARGS...] | bench [NAME [ARGS...]] | sanitize | fuzz [SECONDS] | report [OUTDIR [ARGS...]] | docs" >&2
     exit 2 ;;
esac
