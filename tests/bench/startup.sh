#!/usr/bin/env bash
# Start-up cost (issue 17): wall time and peak memory of `tensorglyph --help`
# and of one-glyph renders, median of N runs each, whole process.
# Usage: tests/bench/startup.sh [BINARY] [N]
set -euo pipefail
bin=${1:-build/tensorglyph}
n=${2:-11}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$bin" synth random --n 1 -o "$dir/one.vtk" >/dev/null
# Wall time from the shell's clock (microseconds; /usr/bin/time rounds to
# 10 ms), peak RSS from /usr/bin/time.
measure() {  # label, then the command
  local label=$1; shift
  for ((k = 0; k < n; k++)); do
    local t0=$EPOCHREALTIME
    /usr/bin/time -f "%M" -o "$dir/t" "$@" >/dev/null 2>&1
    local t1=$EPOCHREALTIME
    echo "$t0 $t1 $(cat "$dir/t")"
  done | awk '{printf "%.1f %d\n", 1000 * ($2 - $1), $3}' | sort -n | awk -v l="$label" '{t[NR]=$1; m[NR]=$2} END {
    mid=int((NR+1)/2); printf "%-30s median %6.1f ms  (min %6.1f, max %6.1f)  peak RSS %6.1f MiB\n",
      l, t[mid], t[1], t[NR], m[mid]/1024}'
}
measure "tensorglyph --help" "$bin" --help
measure "one glyph, 256x256 PNG" "$bin" render "$dir/one.vtk" -o "$dir/one.png" --size 256 256
measure "one glyph, 256x256 EXR" "$bin" render "$dir/one.vtk" -o "$dir/one.exr" --size 256 256
measure "built-in scene, 800x600 PNG" "$bin" render -o "$dir/scene.png" --size 800 600
