#!/bin/bash
# What each depth cue and the legend cost per frame (README, "Depth cues and
# legends"): 10^5 random glyphs at 1024x768 through the default backend,
# ellipsoids and superquadrics, every setting in one run. Each setting runs
# ROUNDS times in rotating order, so that a drift in the machine's load hits
# all alike; a round is `render --repeat 9`, whose median frame it reports.
#   bash tests/bench/cue_costs.sh [BUILD_DIR] [ROUNDS]   (defaults: build 3)
# Prints one line per glyph kind and setting: the median over rounds of the
# per-round median frame time, and its ratio to no effect.
set -euo pipefail
bin=${1:-build}/tensorglyph
rounds=${2:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$bin" synth random --n 100000 --seed 3 -o "$dir/r.vtk" >/dev/null
settings=("none:" "shadows:--shadows" "ao:--ao" "outlines:--outlines" "legend:--legend"
          "all:--shadows --ao --outlines --legend")
for glyph in ellipsoid superquadric; do
  declare -A times=()
  for ((r = 0; r < rounds; r++)); do
    for ((k = 0; k < ${#settings[@]}; k++)); do
      s=${settings[$(((k + r) % ${#settings[@]}))]}
      name=${s%%:*}
      # shellcheck disable=SC2086  # the flags are words
      ms=$("$bin" render "$dir/r.vtk" -o "$dir/o.png" --glyph "$glyph" --repeat 9 --verbose ${s#*:} 2>&1 |
           sed -n 's/.*median of [0-9]* frames \([0-9.]*\) ms.*/\1/p')
      times[$name]="${times[$name]:-} $ms"
    done
  done
  base=$(echo ${times[none]} | tr ' ' '\n' | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  for s in "${settings[@]}"; do
    name=${s%%:*}
    med=$(echo ${times[$name]} | tr ' ' '\n' | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    awk -v g="$glyph" -v n="$name" -v m="$med" -v b="$base" -v all="${times[$name]}" \
      'BEGIN { printf "%-12s %-9s %8.1f ms  x%.2f   (rounds:%s)\n", g, n, m, m / b, all }'
  done
  unset times
done
