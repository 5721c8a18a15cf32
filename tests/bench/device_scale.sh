#!/bin/bash
# The scale sweep on a lent GPU machine, through EGL (README, "GPU runs").
# That machine has no VTK, OpenImageIO or GL loader, so tensorglyph-gpubench
# is built here and carried with glvnd's libraries, fetched once here:
#   mkdir -p .gl /tmp/amd64/partial
#   o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
#   apt-get $o update && (cd .gl && apt-get $o download libegl1 libglvnd0)
# Then, from the device tool:
#   run command="bash tests/bench/device_scale.sh" carry=[".gl", "build/tensorglyph-gpubench"]
# Extra arguments go to tensorglyph-gpubench after the defaults below.
# Results land in $OUT: scale.csv, log.txt and gpu.txt.
set -euo pipefail
out=${OUT:-/tmp/tg-device}
mkdir -p "$out"
# Unpacked into / as the device notes say; only glvnd's own libraries.
for f in .gl/libegl1_*.deb .gl/libglvnd0_*.deb; do dpkg -x "$f" /; done
ldconfig
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
if [[ -f $vendor ]]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; fi
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm,memory.total --format=csv >"$out/gpu.txt" 2>&1 || true
# The compute path first, so that a run cut short keeps its 10^8 rows. Ten
# timed frames a row, the camera turned before each; a row's frames stop after
# 4 s, a method whose warm-up frame passes 3 s skips larger counts, and rows
# that would start after 270 s are skipped (about five minutes in all). The
# CSV is rewritten whole after every row.
build/tensorglyph-gpubench --require-gpu --n 1e4,1e5,1e6,1e7,1e8 --pipelines compute,raster --resolutions 8 \
  --frames 10 --budget 3 --row-budget 4 --total-budget 270 -o "$out/scale.csv" "$@" 2>&1 | tee "$out/log.txt"
