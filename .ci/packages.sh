# Sourced by .ci/build and .ci/run (Debian 12). Two lists: what the CLI and
# its format modules need to build and run (the first command), and what
# the rest of the build and the test suite add (the second).
tg_cli_packages=(cmake g++ make pkg-config libvtk9-dev libosmesa6-dev libegl-dev libegl-mesa0 libglfw3-dev
  libglm-dev libpng-dev libopenimageio-dev libteem-dev libnifti2-dev libimgui-dev libjsoncpp-dev libcli11-dev
  zlib1g-dev libbz2-dev fonts-dejavu-core)
# The Python module, the ParaView plugin, the tests and their peers, the
# fuzzers' toolchain, Xvfb for the display tests, ccache for rebuilds.
tg_test_packages=(pybind11-dev python3-dev python3-numpy libgtest-dev libbenchmark-dev clang libclang-rt-14-dev
  xvfb xauth teem-apps python3-dipy python3-nibabel mrtrix3 paraview paraview-dev openmpi-bin ccache)

# Installs the packages named that dpkg does not list as installed; apt is
# asked only for gaps, so a machine that has them all pays nothing.
tg_install() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "installing: ${missing[*]}"
  apt-get update -qq
  # dpkg's fsync per unpacked file is most of an install on a VM disk; a
  # machine that crashes mid-install is set up again anyway.
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    -o Dpkg::Options::=--force-unsafe-io "${missing[@]}" >/dev/null
}

# Compiler launcher arguments for cmake: ccache where it is installed.
tg_ccache_args() {
  if command -v ccache >/dev/null; then
    echo "-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
  fi
}
