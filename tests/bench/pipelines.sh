#!/usr/bin/env bash
# Glyph paths against each other (issue 33): median frame time of
# `--pipeline raster` and `--pipeline cpu` on the same scenes, in one run,
# and the path `--pipeline auto` took (its calibration measured first, into
# a cache of the run's own, and its time reported apart),
# with the load average before and after: the 2 M-tensor field, the dt-helix
# as ellipsoids and as Kindlmann superquadrics (peers.sh's view), and the
# point load's 64,000 superquadrics (peers.sh's view).
#   bash tests/bench/pipelines.sh [-n N_TENSORS] [-r REPEAT] [-b BUILD_DIR] [-p PRIOR_BUILD]
# Defaults: 2000000 tensors (synth random), 5 frames, build. With -p, the
# tensorglyph of another build (for example the commit before the cpu path,
# built in a worktree) draws each case too, in the same run, with no
# --pipeline (it had one path): columns "prior ms" and "prior / cpu". LP_NUM_THREADS
# is passed through: llvmpipe's threads and the cpu path's (every core)
# run one after the other within a frame, never at once.
# A bench, not a test: not registered in ctest.
set -euo pipefail
n=2000000 repeat=5 build=build prior=
while getopts "n:r:b:p:" opt; do
  case $opt in
    n) n=$OPTARG ;;
    r) repeat=$OPTARG ;;
    b) build=$OPTARG ;;
    p) prior=$(realpath "$OPTARG/tensorglyph") ;;
    *) echo "usage: $0 [-n N_TENSORS] [-r REPEAT] [-b BUILD_DIR] [-p PRIOR_BUILD]" >&2; exit 2 ;;
  esac
done
bin=$(realpath "$build/tensorglyph")
here=$(cd "$(dirname "$0")" && pwd)
helix=$(realpath "$here/../../../shared/data/real/kindlmann-dt-helix/dt-helix.nhdr")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$bin" synth random --n "$n" --seed 3 -o "$dir/random.vtk" >/dev/null
"$bin" synth boussinesq --n 40 -o "$dir/load.vti" --quiet
export TG_CACHE_DIR="$dir/cache"
calStart=$(date +%s.%N)
"$bin" render --pipeline auto --size 64 48 -o "$dir/calibrate.png" --quiet
echo "auto's calibration: $(awk -v a="$calStart" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s (with one small render)"
echo "cores $(nproc), LP_NUM_THREADS ${LP_NUM_THREADS:-unset}, load before: $(cut -d' ' -f1-3 /proc/loadavg)"
ms() { sed -n "s/.*median of [0-9]* frames \([0-9.]*\) ms.*/\1/p" "$1"; }
# The process's CPU time per frame over all threads: on a shared machine,
# what the frame cost apart from waiting for a core.
cpu() { sed -n "s/.*CPU, all threads: \([0-9.]*\) ms.*/\1/p" "$1"; }
rss() { sed -n "s/.*peak RSS \([0-9.]*\) MiB.*/\1/p" "$1"; }
took() { sed -n "s/^  glyph path: \([a-z]*\).*/\1/p" "$1"; }
printf '| %-40s | %10s | %10s | %6s | %13s | %10s | %6s | %10s | %10s | %9s |%s\n' case "raster ms" "cpu ms" "ratio" "raster CPU ms" "cpu CPU ms" \
  "ratio" "raster MiB" "cpu MiB" "auto took" "${prior:+ prior ms | prior / cpu | prior MiB |}"
run() {  # LABEL ARGS...
  local label=$1; shift
  local t=() c=() m=()
  for p in raster cpu; do
    "$bin" render "$@" --pipeline "$p" -o "$dir/$p.png" --repeat "$repeat" --verbose 2>"$dir/$p.err" >/dev/null
    t+=("$(ms "$dir/$p.err")")
    c+=("$(cpu "$dir/$p.err")")
    m+=("$(rss "$dir/$p.err")")
  done
  "$bin" render "$@" --pipeline auto -o "$dir/auto.png" --verbose 2>"$dir/auto.err" >/dev/null
  local extra=""
  if [ -n "$prior" ]; then
    "$prior" render "$@" -o "$dir/prior.png" --repeat "$repeat" --verbose 2>"$dir/prior.err" >/dev/null
    local pt; pt=$(ms "$dir/prior.err")
    extra=" $pt | $(awk -v a="$pt" -v b="${t[1]}" 'BEGIN { printf "%.1f", a / b }')x | $(rss "$dir/prior.err") |"
  fi
  printf '| %-40s | %10s | %10s | %5sx | %13s | %10s | %5sx | %10s | %10s | %9s |%s\n' "$label" "${t[0]}" "${t[1]}" \
    "$(awk -v a="${t[0]}" -v b="${t[1]}" 'BEGIN { printf "%.1f", a / b }')" "${c[0]}" "${c[1]}" \
    "$(awk -v a="${c[0]}" -v b="${c[1]}" 'BEGIN { printf "%.1f", a / b }')" "${m[0]}" "${m[1]}" "$(took "$dir/auto.err")" "$extra"
}
run "synth random $n, 1920x1080" "$dir/random.vtk" --size 1920 1080
helixView=(--size 512 512 --scale-mode absolute --scale 0.12 --eye 5.4 -9.6 7.5 --look-at 0 0 0 --up 0 0 1 --fov 30)
run "dt-helix ellipsoids, 512x512" "$helix" --glyph ellipsoid "${helixView[@]}"
run "dt-helix superquadrics g3, 512x512" "$helix" --glyph superquadric --gamma 3 "${helixView[@]}"
run "point load 40^3 superquadrics, 1024x768" "$dir/load.vti" --glyph superquadric --gamma 3 --size 1024 768 \
  --scale-mode absolute --scale 0.108 --clamp 2 --eye 2.0 -3.3 1.2 --look-at 0 0 -1 --up 0 0 1 --fov 30
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
