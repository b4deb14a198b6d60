#!/usr/bin/env bash
# ShrinkWrap on a fresh Debian 12 machine, as root: installs what is missing (Debian packages only),
# configures, builds, then runs one of
#   demo   the main job on the default data (Data/trefoil.obj): out/trefoil_sdf.vti and .png
#   test   the whole test suite through ctest, then the C++ tests again under AddressSanitizer
#   bench  the benchmarks of Testing/Benchmarks (peers: OpenVDB, vtkImplicitPolyDataDistance, CGAL 6.0's
#          and 5.5's alpha wrap)
#   packages  prints the Debian packages that the build folder's configuration may use
# Every step is idempotent: a second run only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")"
mode="${1:-demo}"
build="${SHRINKWRAP_BUILD:-$PWD/build}"
jobs="$(nproc)"

# Debian packages, by what needs them. Testing/check_packages.py (run by `test`) fails when the build
# resolves a file from a package this list does not bring: a machine that has one by chance hides it.
packages=(
  cmake ninja-build g++                       # the build
  paraview paraview-dev python3-paraview      # ParaView 5.11 and its VTK: headers, CMake config, pvpython, GUI
  libeigen3-dev                               # the evolver's sparse solvers
  # find_package(ParaView) asks for these Qt5 modules (ParaView's Qt components)
  qtbase5-dev libqt5opengl5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools
  # ParaView's VTK config finds its third-party libraries through these
  libhdf5-dev libnetcdf-dev libgdal-dev libboost-dev libavcodec-dev libavformat-dev libavutil-dev
  libswscale-dev libgl2ps-dev libglew-dev libtheora-dev libtiff-dev libjpeg-dev liblz4-dev liblzma-dev
  libdouble-conversion-dev libutfcpp-dev libexpat1-dev libfreetype-dev libfontconfig-dev libpng-dev
  libxml2-dev libxml2-utils
  mpi-default-dev mpi-default-bin             # VTK's config finds MPI; mpiexec runs the MPI test
  # X11 and OpenGL for rendering; FindX11 also takes the optional X libraries it finds, so they are
  # listed for a fresh machine to configure as CI's does
  libx11-dev libgl-dev libice-dev libsm-dev libxcomposite-dev libxfixes-dev libxft-dev libxrender-dev
  libxss-dev libxt-dev
  xvfb xauth                                  # an X server for the rendering and GUI tests, the demo's picture
  imagemagick                                 # the GUI test's picture of the Properties panel (import)
)
bench_packages=(libopenvdb-dev libboost-iostreams-dev libcgal-dev) # the benchmarks' peers: OpenVDB, CGAL
[ "$mode" = bench ] && packages+=("${bench_packages[@]}")
# The packages a build folder's configuration may resolve: with the benchmarks (once `bench` ran in
# it), their peers' too.
checked=("${packages[@]}")
if [ "$mode" != bench ] && grep -qs '^SHRINKWRAP_BENCHMARKS:BOOL=ON' "$build/CMakeCache.txt"; then
  checked+=("${bench_packages[@]}")
fi

install_missing() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "== installing: ${missing[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
}

# CGAL's mesh data set (bunny00, armadillo, knot1, elephant-with-holes, ...) from Debian's libcgal-demo.
fetch_cgal_meshes() {
  local dir="$build/cgal"
  [ -f "$dir/data/meshes/bunny00.obj" ] && return
  echo "== fetching CGAL's meshes (libcgal-demo)"
  mkdir -p "$dir" && (cd "$dir" && rm -f libcgal-demo_*.deb &&
    { apt-get download libcgal-demo >/dev/null 2>&1 || { apt-get update -qq && apt-get download libcgal-demo >/dev/null; }; } &&
    dpkg -x libcgal-demo_*.deb deb &&
    tar xzf deb/usr/share/doc/libcgal-dev/data.tar.gz data/meshes && rm -rf deb libcgal-demo_*.deb)
  # ParaView reads OBJ but not OFF: the bunny of the GUI test, converted.
  awk 'BEGIN { n = -1 } /^#/ || NF == 0 { next }
       n < 0 { if ($1 == "OFF") next; nv = $1; n = 0; next }
       n < nv { print "v", $1, $2, $3; n++; next }
       { printf "f"; for (i = 2; i <= $1 + 1; i++) printf " %d", $i + 1; print "" }' \
    "$dir/data/meshes/bunny00.off" > "$dir/data/meshes/bunny00.obj"
}

# CGAL 6.0's headers (Debian 13's libcgal-dev 6.0.1, header-only) for the alpha wrap users have today,
# downloaded through a sources list of their own and unpacked into the build folder: nothing on the
# system changes. The benchmarks build the peer against them beside the system's CGAL 5.5.
fetch_cgal6() {
  local dir="$build/cgal6"
  [ -f "$dir/usr/include/CGAL/version.h" ] && return
  echo "== fetching CGAL 6.0 (Debian 13's libcgal-dev, into $dir)"
  local apt="$dir/apt"
  mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial"
  echo "deb http://deb.debian.org/debian trixie main" > "$apt/sources.list"
  local options=(-o Dir::Etc::SourceList="$apt/sources.list" -o Dir::Etc::SourceParts=/dev/null
    -o Dir::State::Lists="$apt/lists" -o Dir::Cache="$apt/cache")
  apt-get "${options[@]}" update -qq &&
    (cd "$apt" && apt-get "${options[@]}" download libcgal-dev >/dev/null 2>&1) &&
    dpkg -x "$apt"/libcgal-dev_6.*.deb "$dir" && rm -rf "$apt"
}

configure_and_build() { # folder, extra cmake arguments...
  local dir="$1"; shift
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHRINKWRAP_CGAL_MESHES="$build/cgal/data/meshes" "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
}

[ "$mode" = packages ] && { printf '%s\n' "${checked[@]}"; exit 0; }
install_missing
plugin="$build/lib/paraview-5.11/plugins/ShrinkWrap/ShrinkWrap.so"
case "$mode" in
  demo)
    configure_and_build "$build"
    Testing/run-with-x.sh pvbatch Examples/demo.py "$plugin" Data/trefoil.obj out
    ;;
  test)
    fetch_cgal_meshes
    configure_and_build "$build"
    python3 Testing/check_packages.py "$build/CMakeCache.txt" "${checked[@]}"
    (cd "$build" && ctest --output-on-failure -j 2)
    # Bad input, the honest results, the pipeline, the surface edits, the gap closing and the point
    # distances once more under AddressSanitizer and UBSan: bad input must not corrupt memory. (The
    # other accuracy tests' brute-force references are too slow instrumented.)
    configure_and_build "$build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHRINKWRAP_SANITIZE=ON \
      -DSHRINKWRAP_FUZZ_SECONDS=90
    (cd "$build-asan" && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
      ctest --output-on-failure -j 2 -R "BadInput|HonestResults|Filter|StartingSurface|Fuzz|SurfaceMesh|Edge|Remesher|TestEvolver$|SlabDistance|GapClosing|PointDistance|PointSurface|SelfIntersections")
    ;;
  bench)
    fetch_cgal_meshes
    fetch_cgal6
    configure_and_build "$build" -DSHRINKWRAP_BENCHMARKS=ON -DSHRINKWRAP_CGAL6_INCLUDE="$build/cgal6/usr/include"
    bash Testing/Benchmarks/run.sh "$build"
    ;;
  *)
    echo "usage: bash shrinkwrap.sh demo|test|bench" >&2
    exit 2
    ;;
esac
