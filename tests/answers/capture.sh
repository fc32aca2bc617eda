#!/usr/bin/env bash
# Stores the answers of every case in cases.txt: `bash tests/answers/capture.sh [BUILD_DIR]`
# runs each through the built command line (BUILD_DIR/src/cli/cosmems, build/release by default)
# and keeps its JSON (answer.json) and the CSV files of its --out folder in tests/answers/NAME/.
# Run it only for a deliberate change of answers, and say in the commit which numbers moved and
# why: the suite holds every later build to these files (tests/cli/stored_answers_test.cpp).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=$(cd "${1:-build/release}" && pwd)/src/cli/cosmems
failed=0
while read -r name scene settings; do
  case "$name" in '' | '#'*) continue ;; esac
  args=()
  for setting in $settings; do args+=(--set "$setting"); done
  rm -rf "${here:?}/$name"
  mkdir -p "$here/$name"
  if ! "$binary" run "$scene" "${args[@]}" --json --out "$here/$name" > "$here/$name/answer.json"; then
    echo "capture.sh: case $name failed" >&2
    failed=1
  fi
done < "$here/cases.txt"
exit $failed
