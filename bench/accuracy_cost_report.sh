#!/usr/bin/env bash
# The accuracy-versus-time report in one command:
#   bash bench/accuracy_cost_report.sh OUTDIR [GOOGLE BENCHMARK FLAGS...]
# runs accuracy_cost_bench (every setting of every reference problem; times are medians of five
# repetitions), which writes OUTDIR/accuracy_cost.csv and OUTDIR/accuracy_cost.md, keeps its
# console output in OUTDIR/accuracy_cost.log, and plots the CSV with bench/accuracy_cost.gp into
# OUTDIR/accuracy_cost*.png. Extra flags go to the benchmark (e.g. --benchmark_filter=release).
# Needs the benchmark built in COSMEMS_BUILD_DIR (default build/release, as cmake/bootstrap.sh
# builds it: `bash cmake/bootstrap.sh bench`) and gnuplot (Debian: gnuplot-nox).
set -euo pipefail

if [ $# -lt 1 ]; then
  echo "usage: bash bench/accuracy_cost_report.sh OUTDIR [GOOGLE BENCHMARK FLAGS...]" >&2
  exit 2
fi
out=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
build_dir=${COSMEMS_BUILD_DIR:-build/release}
case "$build_dir" in
  /*) ;;
  *) build_dir="$(dirname "$here")/$build_dir" ;;
esac
bench="$build_dir/bench/accuracy_cost_bench"
if [ ! -x "$bench" ]; then
  echo "$bench is missing: build the target accuracy_cost_bench (bash cmake/bootstrap.sh bench)" >&2
  exit 1
fi
if ! command -v gnuplot >/dev/null; then
  echo "gnuplot is missing: apt-get install gnuplot-nox" >&2
  exit 1
fi
case "$out" in
  *\'*) echo "OUTDIR must not contain a single quote (it is passed to gnuplot): $out" >&2; exit 2 ;;
esac

mkdir -p "$out"
"$bench" --report_dir="$out" --benchmark_repetitions=5 --benchmark_min_time=0.05 \
  --benchmark_report_aggregates_only=true "$@" | tee "$out/accuracy_cost.log"
gnuplot -e "dir='$out'" "$here/accuracy_cost.gp"
echo "plots: $out/accuracy_cost.png and $out/accuracy_cost_*.png"
