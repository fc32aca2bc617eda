#!/usr/bin/env bash
# Fails when a library header or source includes a layer above its own. The order is that of
# doc/architecture.md, lowest first; a folder may include itself and any folder ranked below it.
# Two folders of one rank (the device backends) may not include each other. Programs (src/cli,
# src/viewer, src/python, examples, bench, tests) sit on top and may include anything.
# Usage: check_layers.sh ROOT   (ROOT holds include/cosmems and src)
set -euo pipefail
root=${1:?usage: check_layers.sh ROOT}
declare -A rank=([core]=0 [linalg]=1 [beam]=2 [structure]=3 [rod]=4 [surface]=5 [time]=6
  [analysis]=7 [scene]=8 [haptics]=9 [scripted]=10 [openhaptics]=10 [session]=11)
status=0
for dir in "${!rank[@]}"; do
  for tree in "$root/include/cosmems/$dir" "$root/src/$dir"; do
    [ -d "$tree" ] || continue
    while IFS=: read -r file line text; do
      target=$(sed -E 's|.*"cosmems/([a-z_]+)/.*|\1|' <<<"$text")
      if [ -z "${rank[$target]+x}" ]; then
        echo "$file:$line: includes unknown layer '$target'" >&2
        status=1
      elif [ "$target" != "$dir" ] && [ "${rank[$target]}" -ge "${rank[$dir]}" ]; then
        echo "$file:$line: $dir/ (layer ${rank[$dir]}) includes $target/ (layer ${rank[$target]})" >&2
        status=1
      fi
    done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"cosmems/[a-z_]+/' "$tree" || true)
  done
done
exit $status
