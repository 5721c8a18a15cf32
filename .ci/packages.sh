# Sourced by .ci/build and .ci/run (Debian 12). Two lists: what the CLI and
# its format modules need to build and run (the first command), and what
# the rest of the build and the test suite add (the second).
# VTK comes as its runtime libraries (libvtk9.1) and the -dev packages its
# CMake files look for with the modules CMakeLists.txt asks for; its headers
# and CMake files are unpacked privately (tg_vtk_dir below), as libvtk9-dev
# itself depends on some 270 packages (Java, GDAL, HDF5, MPI headers,
# python3-vtk9) none of those modules need.
tg_cli_packages=(cmake g++ make pkg-config libvtk9.1 libexpat1-dev libdouble-conversion-dev liblz4-dev
  liblzma-dev libjpeg-dev libtiff-dev libtbb-dev libutfcpp-dev libosmesa6-dev libegl-dev libegl-mesa0
  libglfw3-dev libglm-dev libpng-dev libopenimageio-dev libteem-dev libnifti2-dev libimgui-dev libjsoncpp-dev
  libcli11-dev zlib1g-dev libbz2-dev fonts-dejavu-core)
# The Python module, the ParaView plugin, the tests and their peers (VTK's
# Python modules among them: libvtk9-dev whole), the fuzzers' toolchain,
# Xvfb for the display tests, ccache for rebuilds.
tg_test_packages=(libvtk9-dev pybind11-dev python3-dev python3-numpy libgtest-dev libbenchmark-dev clang
  libclang-rt-14-dev xvfb xauth teem-apps python3-dipy python3-nibabel mrtrix3 paraview paraview-dev openmpi-bin
  ccache)

# Installs the packages named that dpkg does not list as installed; apt is
# asked only for gaps, so a machine that has them all pays nothing.
tg_install() {
  local missing=() p
  for p in "$@"; do
    tg_installed "$p" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "installing: ${missing[*]}"
  apt-get update -qq
  # dpkg's fsync per unpacked file is most of an install on a VM disk; a
  # machine that crashes mid-install is set up again anyway.
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    -o Dpkg::Options::=--force-unsafe-io "${missing[@]}" >/dev/null
}

tg_installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "ok installed"; }

# Prints the directory of VTK's CMake files (for -DVTK_DIR): the system's
# where libvtk9-dev is installed, otherwise that package, of the installed
# libvtk9.1's version, unpacked under $1, with its library links pointing at
# libvtk9.1's files and VTK's Python and Java wrapping (packages not
# installed) switched off in its vtk-config.cmake.
tg_vtk_dir() {
  local arch cmake_dir version dir tmp f
  arch=$(gcc -print-multiarch) || return
  cmake_dir=usr/lib/$arch/cmake/vtk-9.1
  if tg_installed libvtk9-dev; then
    echo "/$cmake_dir"
    return
  fi
  version=$(dpkg-query -W -f='${Version}' libvtk9.1) || return
  dir=$(mkdir -p "$1" && cd "$1" && pwd) || return
  if [ "$(cat "$dir/version" 2>/dev/null)" != "$version" ]; then
    tmp=$(mktemp -d) || return
    # apt fetches as _apt, which must be able to write there.
    chown _apt "$tmp" 2>/dev/null || true
    (cd "$tmp" && { apt-get download -qq "libvtk9-dev=$version" ||
      { apt-get update -qq && apt-get download -qq "libvtk9-dev=$version"; }; }) &&
      rm -rf "$dir" && dpkg-deb -x "$tmp"/libvtk9-dev_*.deb "$dir" || { rm -rf "$tmp"; return 1; }
    rm -rf "$tmp"
    for f in /usr/lib/"$arch"/libvtk*-9.1.so.*; do
      ln -sf "$f" "$dir/usr/lib/$arch/" || return
    done
    sed -i 's/_WRAP_\(PYTHON\|JAVA\)" "ON")/_WRAP_\1" "OFF")/' "$dir/$cmake_dir/vtk-config.cmake" &&
      echo "$version" >"$dir/version" || return
  fi
  echo "$dir/$cmake_dir"
}

# Compiler launcher arguments for cmake: ccache where it is installed.
tg_ccache_args() {
  if command -v ccache >/dev/null; then
    echo "-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
  fi
}
