#!/bin/bash
# What a 1M-triangle context mesh adds to a frame (README, "Meshes in
# context"): 10^5 random glyphs at 1024x768 through the default backend, with
# no mesh and with a 1,000,000-triangle sphere (binary STL) through the middle
# of the field in each drawing mode, inside the glyphs as an FEM part is; then
# the same with every glyph hidden (--fa-min 1), the mesh in full view. Each setting runs ROUNDS times in
# rotating order, so that a drift in the machine's load hits all alike; a
# round is `render --repeat 9`, whose median frame it reports.
#   bash tests/bench/mesh_cost.sh [BUILD_DIR] [ROUNDS]   (defaults: build 3)
# Prints one line per setting: the median over rounds of the per-round
# median frame time, and what it adds to no mesh (alone-*: to no mesh and no glyphs).
set -euo pipefail
bin=${1:-build}/tensorglyph
rounds=${2:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$bin" synth random --n 100000 --seed 3 -o "$dir/r.vtk" >/dev/null
# A UV sphere of 1000 x 500 quads (10^6 triangles), radius 18, around the
# random field's grid centre (about 23, 23, 22).
python3 - "$dir/sphere.stl" <<'PY'
import math, struct, sys
nt, npf, r, c = 1000, 500, 18.0, (23.0, 23.0, 22.0)
def p(i, j):
    th, ph = 2 * math.pi * i / nt, math.pi * j / npf
    return (c[0] + r * math.cos(th) * math.sin(ph), c[1] + r * math.sin(th) * math.sin(ph), c[2] + r * math.cos(ph))
with open(sys.argv[1], "wb") as f:
    f.write(b"\0" * 80 + struct.pack("<I", 2 * nt * npf))
    rec = struct.Struct("<12fH")
    for j in range(npf):
        for i in range(nt):
            a, b, cc, d = p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)
            f.write(rec.pack(0, 0, 0, *a, *b, *cc, 0))
            f.write(rec.pack(0, 0, 0, *a, *cc, *d, 0))
PY
settings=("none:" "opaque:--mesh $dir/sphere.stl" "see-through:--mesh $dir/sphere.stl --mesh-mode see-through"
          "edges:--mesh $dir/sphere.stl --mesh-mode edges" "alone-none:--fa-min 1"
          "alone-opaque:--fa-min 1 --mesh $dir/sphere.stl"
          "alone-see-through:--fa-min 1 --mesh $dir/sphere.stl --mesh-mode see-through")
declare -A times=()
for ((r = 0; r < rounds; r++)); do
  for ((k = 0; k < ${#settings[@]}; k++)); do
    s=${settings[$(((k + r) % ${#settings[@]}))]}
    name=${s%%:*}
    # shellcheck disable=SC2086  # the flags are words
    ms=$("$bin" render "$dir/r.vtk" -o "$dir/o.png" --repeat 9 --verbose ${s#*:} 2>&1 |
         sed -n 's/.*median of [0-9]* frames \([0-9.]*\) ms.*/\1/p')
    times[$name]="${times[$name]:-} $ms"
  done
done
med() { echo "$@" | tr ' ' '\n' | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
for s in "${settings[@]}"; do
  name=${s%%:*}
  base=$(med ${times[none]})
  [[ $name == alone-* ]] && base=$(med ${times[alone-none]})
  m=$(med ${times[$name]})
  awk -v n="$name" -v m="$m" -v b="$base" -v all="${times[$name]}" \
    'BEGIN { printf "%-12s %8.1f ms  +%.1f ms   (rounds:%s)\n", n, m, m - b, all }'
done
