#!/usr/bin/env bash
# Peer comparison (issue 17): tensorglyph against Teem's ray tracer (`tend
# glyph -rt`, teem-apps) and VTK's vtkTensorGlyph (Debian's python3-vtk9,
# under Xvfb), on the same fields, glyph sizes, cameras and image sizes, each
# row naming the shape it draws: ellipsoids against VTK's sphere source,
# Kindlmann's superquadrics against Teem's and against VTK's superquadric
# source (one torus shape, as ParaView sets it up; a different shape).
# Prints a table of whole-process wall time (median of N runs), frame time
# where the tool reports one, peak resident memory (/usr/bin/time, the
# largest process of the run) and the ratios, then how far the images agree:
# the pixels each covers and the pixels covered by one image only.
#   bash tests/bench/peers.sh [-n N] [-b BUILD_DIR] [-v VTK_RUNS]
# Defaults: N 3, build, VTK_RUNS 1 (runs of each of the two VTK cases; one
# takes minutes and gigabytes; -v 0 skips VTK). A bench, not a test: not registered in ctest.
set -euo pipefail
n=3 build=build vtk_runs=1
while getopts "n:b:v:" opt; do
  case $opt in
    n) n=$OPTARG ;;
    b) build=$OPTARG ;;
    v) vtk_runs=$OPTARG ;;
    *) echo "usage: $0 [-n N] [-b BUILD_DIR] [-v VTK_RUNS]" >&2; exit 2 ;;
  esac
done
bin=$(realpath "$build/tensorglyph")
here=$(cd "$(dirname "$0")" && pwd)
helix=$(realpath "$here/../../../shared/data/real/kindlmann-dt-helix/dt-helix.nhdr")
python=/usr/bin/python3  # Debian's, with python3-vtk9; not a pyenv python3 on PATH
dir=$(mktemp -d)
xvfb=
trap '[ -n "$xvfb" ] && kill "$xvfb"; rm -rf "$dir"' EXIT
cd "$dir"
load0=$(cut -d' ' -f1-3 /proc/loadavg)

# measure LABEL CMD...: $runs runs; writes "median_wall_s median_peak_MiB" to
# LABEL.med, the last run's stdout to LABEL.out and every run's stderr to
# LABEL.errs.
measure() {
  local label=$1; shift
  : >"$label.errs"
  for ((k = 0; k < runs; k++)); do
    local t0=$EPOCHREALTIME
    /usr/bin/time -f "%M" -o "$label.rss" "$@" >"$label.out" 2>>"$label.errs"
    local t1=$EPOCHREALTIME
    echo "$t0 $t1 $(cat "$label.rss")"
  done | awk '{print $2 - $1, $3 / 1024}' >"$label.times"
  echo "$(median 1 <"$label.times") $(median 2 <"$label.times")" >"$label.med"
}
median() { sort -g -k"$1" | awk -v c="$1" '{a[NR]=$c} END {printf "%.3f", a[int((NR+1)/2)]}'; }
# Pixels where a 0/1 nrrd (or two, "neq") is 1.
count() { teem-unu project -i - -a 0 -m sum | teem-unu project -a 0 -m sum | teem-unu save -f text; }
# Our PNG's alpha (background 0 0 0 0) as a 0/1 mask.
ours_mask() { teem-unu slice -i "$1" -a 0 -p 3 | teem-unu 2op gt - 127 -o "$2"; }
ms() { sed -n "s/.*median of [0-9]* frames \([0-9.]*\) ms.*/\1/p" "$1"; }
rows=()
row() { rows+=("$(printf '| %s | %s | %s | %s | %s |' "$@")"); }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a > 0 && b > 0) printf "%.1fx", a / b; else print "-" }'; }

# ---- Kindlmann's dt-helix against `tend glyph -rt` --------------------------
# 59,280 superquadrics, gamma 3, 512x512, every glyph drawn; semi-axes 0.06 |l|
# (Teem's -gsc 0.06, our --scale-mode absolute --scale 0.12, a diameter); one sample per pixel centre.
# Teem's gage refuses the file's own axis mins/maxs ("need some spacing
# info") and, given spacings alone, fits the grid into [-1, 1]; so Teem reads
# the same raw data through a header that states the grid we read from the
# original (cell-centred samples of [-2, 2]) as space directions and origin.
sed -e '/^axis m/d' -e "s|^data file: \./|data file: $(dirname "$helix")/|" -e 's/^NRRD0001/NRRD0005/' \
    -e 's/^dimension: 4/dimension: 4\nspace dimension: 3\nkinds: 3D-masked-symmetric-matrix space space space/' \
    -e 's|^sizes: 7 38 39 40|&\nspace directions: none (0.10526315789473684,0,0) (0,0.10256410256410256,0) (0,0,0.1)\nspace origin: (-1.9473684210526316,-1.9487179487179487,-1.95)|' \
    "$helix" >teem-helix.nhdr
eye="5.4 -9.6 7.5"
runs=$n
measure tg-helix "$bin" render "$helix" -o tg-helix.png --glyph superquadric --gamma 3 \
  --size 512 512 --scale-mode absolute --scale 0.12 --eye $eye --look-at 0 0 0 --up 0 0 1 --fov 30 --background 0 0 0 0
read -r tg_s tg_mb <tg-helix.med
"$bin" render "$helix" -o tg-helix.png --glyph superquadric --gamma 3 --size 512 512 --scale-mode absolute --scale 0.12 --eye $eye \
  --look-at 0 0 0 --up 0 0 1 --fov 30 --background 0 0 0 0 --repeat 7 --verbose 2>tg-helix-frames.err
tg_ms=$(ms tg-helix-frames.err)
# The same frames on the cpu glyph path (issue 33's target: 10x echoRTRender).
measure tg-helix-cpu "$bin" render "$helix" -o tg-helix-cpu.png --glyph superquadric --gamma 3 --pipeline cpu \
  --size 512 512 --scale-mode absolute --scale 0.12 --eye $eye --look-at 0 0 0 --up 0 0 1 --fov 30 --background 0 0 0 0
read -r tgc_s tgc_mb <tg-helix-cpu.med
"$bin" render "$helix" -o tg-helix-cpu.png --glyph superquadric --gamma 3 --pipeline cpu --size 512 512 --scale-mode absolute \
  --scale 0.12 --eye $eye --look-at 0 0 0 --up 0 0 1 --fov 30 --background 0 0 0 0 --repeat 7 --verbose 2>tg-helix-cpu-frames.err
tgc_ms=$(ms tg-helix-cpu-frames.err)
measure teem-helix teem-tend glyph -rt -i teem-helix.nhdr -o teem-helix.nrrd -g superquad \
  -sh 3 -gsc 0.06 -atr -1 -ctr 0.5 -fr $eye -at 0 0 0 -up 0 0 1 -fv 30 -dn -12 -df 13.4 -is 512 512 -ns 1 -nt 2
read -r te_s te_mb <teem-helix.med
te_ms=$(sed -n 's/.*echoRTRender: time = \([0-9.]*\).*/\1/p' teem-helix.errs | median 1 | awk '{printf "%.1f", 1000 * $1}')
row "dt-helix, 59,280 superquadrics, 512x512" "tensorglyph, Kindlmann superquadrics (gamma 3)" "$tg_s" "$tg_ms" "$tg_mb"
row "" "\`tend glyph -rt -nt 2\`, Kindlmann superquadrics (gamma 3)" "$te_s" "$te_ms (echoRTRender)" "$te_mb"
row "" "Teem / tensorglyph" "$(ratio "$te_s" "$tg_s")" "$(ratio "$te_ms" "$tg_ms")" "$(ratio "$te_mb" "$tg_mb")"
row "" "tensorglyph \`--pipeline cpu\`, the same superquadrics" "$tgc_s" "$tgc_ms" "$tgc_mb"
row "" "Teem / tensorglyph cpu" "$(ratio "$te_s" "$tgc_s")" "$(ratio "$te_ms" "$tgc_ms")" "$(ratio "$te_mb" "$tgc_mb")"
# Teem's image V axis points up: its row 0 is our bottom row.
teem-unu slice -i teem-helix.nrrd -a 0 -p 3 | teem-unu 2op gt - 0.5 | teem-unu flip -a 1 -o teem-helix-mask.nrrd
ours_mask tg-helix.png tg-helix-mask.nrrd
cover=("dt-helix: tensorglyph covers $(count <tg-helix-mask.nrrd) px, Teem $(count <teem-helix-mask.nrrd) px;"
       "covered by one only: $(teem-unu 2op neq tg-helix-mask.nrrd teem-helix-mask.nrrd | count) px")

# ---- Point load 40^3 against vtkTensorGlyph -----------------------------------
# 64,000 indefinite stress tensors at 1024x768; semi-axes 0.054 |l|, every
# glyph clamped to 2 sample spacings across (ours: --clamp 2; VTK:
# ClampScaling, MaxScaleFactor 2 spacings). Like shapes against each other:
# our exact ellipsoids against VTK's 16x16 sphere source (an ellipsoid per
# glyph, ParaView's "Sphere" glyph type); our Kindlmann superquadrics (gamma
# 3, each glyph's shape from its anisotropy) against VTK's 16x16 superquadric
# source as ParaView's TensorGlyph sets it up (toroidal, roundness 1: one
# torus shape for every glyph). VTK has no Kindlmann superquadric: that pair
# is what a ParaView user asking for superquadrics gets, named for what it is.
"$bin" synth boussinesq --n 40 -o load.vti --quiet
spacing=$("$bin" info load.vti --quiet | sed -n 's/^sample spacing: //p')
eye="2.0 -3.3 1.2"
cam=(--eye $eye --look-at 0 0 -1 --up 0 0 1 --fov 30)
# load_case LABEL GLYPH_ARGS...: times our render of the point load (whole
# process and --repeat 7 frames); sets tg_s, tg_mb and tg_ms.
load_case() {
  local label=$1; shift
  runs=$n
  measure "$label" "$bin" render load.vti -o "$label.png" "$@" --size 1024 768 --scale-mode absolute --scale 0.108 --clamp 2 \
    "${cam[@]}" --background 0 0 0 0
  read -r tg_s tg_mb <"$label.med"
  "$bin" render load.vti -o "$label.png" "$@" --size 1024 768 --scale-mode absolute --scale 0.108 --clamp 2 "${cam[@]}" \
    --background 0 0 0 0 --repeat 7 --verbose 2>"$label-frames.err"
  tg_ms=$(ms "$label-frames.err")
}
# vtk_case LABEL SOURCE NAME: times peer_vtk_glyph.py with SOURCE against the
# tg_* figures just measured, and adds its rows and notes.
vtk_case() {
  local label=$1 source=$2 name=$3
  runs=$vtk_runs
  measure "$label" "$python" "$here/peer_vtk_glyph.py" load.vti 1024 768 $eye 0 0 -1 0 0 1 30 \
    0.054 "$(awk -v s="$spacing" 'BEGIN { print 2 * s }')" 16 "$source" "$label-mask.png"
  local vtk_s vtk_mb vtk_build vtk_first vtk_frame vtk_ms
  read -r vtk_s vtk_mb <"$label.med"
  read -r vtk_build vtk_first vtk_frame <"$label.out"
  vtk_ms=$(awk -v s="$vtk_frame" 'BEGIN { printf "%.0f", 1000 * s }')
  row "" "$name" "$vtk_s" "$vtk_ms" "$vtk_mb"
  row "" "VTK / tensorglyph" "$(ratio "$vtk_s" "$tg_s")" "$(ratio "$vtk_ms" "$tg_ms")" "$(ratio "$vtk_mb" "$tg_mb")"
  notes+=("$name: builds the glyphs in ${vtk_build} s and draws the frame twice: first ${vtk_first} s"
          "(with its buffers), then ${vtk_frame} s, its frame time; median of $vtk_runs run(s).")
}
notes=()
if ((vtk_runs > 0)); then
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>display 2>/dev/null &
  xvfb=$!
  for ((k = 0; k < 50; k++)); do [[ -s display ]] && break; sleep 0.1; done
  export DISPLAY=:$(cat display)
fi
load_case tg-load-ell --glyph ellipsoid
row "point load 40^3, 64,000 ellipsoids, 1024x768" "tensorglyph, exact ellipsoids" "$tg_s" "$tg_ms" "$tg_mb"
if ((vtk_runs > 0)); then
  vtk_case vtk-load-sphere sphere "vtkTensorGlyph, vtkSphereSource 16x16 (ellipsoids)"
  read -r ours theirs either far_ours far_theirs < <("$python" "$here/peer_mask_diff.py" tg-load-ell.png 3 vtk-load-sphere-mask.png 0)
  cover+=("point load, ellipsoids against VTK's sphere source: tensorglyph covers $ours px, VTK $theirs px; covered by one only:"
          "$either px; farther than one pixel from the other's coverage: $far_ours px of ours, $far_theirs px of VTK's")
fi
load_case tg-load --glyph superquadric --gamma 3
row "point load 40^3, 64,000 superquadrics, 1024x768" "tensorglyph, Kindlmann superquadrics (gamma 3)" "$tg_s" "$tg_ms" "$tg_mb"
if ((vtk_runs > 0)); then
  vtk_case vtk-load-sq superquadric "vtkTensorGlyph, vtkSuperquadricSource 16x16 as ParaView sets it (one torus shape, not Kindlmann's)"
  read -r ours theirs either far_ours far_theirs < <("$python" "$here/peer_mask_diff.py" tg-load.png 3 vtk-load-sq-mask.png 0)
  cover+=("point load, Kindlmann superquadrics against VTK's toroidal superquadric source (different shapes, not an error):"
          "tensorglyph covers $ours px, VTK $theirs px; covered by one only: $either px")
else
  ours_mask tg-load.png tg-load-mask.nrrd
  cover+=("point load: tensorglyph's ellipsoids cover $(ours_mask tg-load-ell.png e.nrrd && count <e.nrrd) px,"
          "its superquadrics $(count <tg-load-mask.nrrd) px")
fi

echo "Load average at the start: $load0; at the end: $(cut -d' ' -f1-3 /proc/loadavg)."
echo "Whole process: median of $n runs (wall, from the shell's clock); frame: tensorglyph's median of 7 (--repeat 7),"
echo "Teem's own echoRTRender time, VTK's second Render(). $(nproc) cores: $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)."
echo
echo "| Case | Tool and the shape it draws | Whole process (s) | Frame (ms) | Peak memory (MiB) |"
echo "|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
echo
printf '%s\n' "${notes[@]}" "${cover[@]}"
