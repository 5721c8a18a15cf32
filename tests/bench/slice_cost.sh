#!/bin/sh
# What one slice plane adds to a frame (not a test): the median of N frames of
# the same render with and without `--underlay fa`, and the GPU memory the
# plane holds. Usage: tests/bench/slice_cost.sh [BINARY] [INPUT] [N]
set -eu
bin=${1:-build/tensorglyph}
input=${2:-../shared/data/real/slicer-helix-dti-masked/helix-DTI.nhdr}
n=${3:-30}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for extra in "" "--underlay ${input%/*}/helix-DTI-FractionalAnisotropy.nhdr" "--underlay fa"; do
  printf '%-70s ' "${extra:-no plane}"
  "$bin" render "$input" -o "$out/f.png" --size 1024 768 --repeat "$n" $extra 2>&1 |
    sed -n 's/.*median of [0-9]* frames \([0-9.]*\) ms.*/\1 ms/p'
done
