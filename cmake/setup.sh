#!/usr/bin/env bash
# AdaptiveRT set-up: installs the Debian packages it needs (only those missing, so a second run
# is fast), configures and builds in Release with ninja, then optionally runs something. The
# configure step downloads MMG (the pinned mmgpy wheel, cmake/AdaptiveRTMmg.cmake) over HTTPS,
# hence ca-certificates; no python or pip is involved.
#   cmake/setup.sh          set up and build
#   cmake/setup.sh demo     ... then run the main job on the embedded default data
#   cmake/setup.sh test     ... then run every test through ctest (under Xvfb when no display)
#   cmake/setup.sh fuzz [S] ... then build the loaders' fuzzing targets with clang (tests/fuzz) and
#                           run each for S seconds (default 120); not part of CI
#   cmake/setup.sh paraview ... then build the ParaView plugin in build/paraview and run its tests
#                           (paraview/setup.sh; writes build/paraview/env.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  g++ cmake ninja-build pkg-config ccache git ca-certificates
  libvtk9-dev python3-vtk9 python3-matplotlib
  libopenimageio-dev libtbb-dev
  libgtest-dev libembree-dev nlohmann-json3-dev
  libcgal-dev libtet1.5-dev   # CGAL Mesh_3 (brings GMP, MPFR, Boost headers), TetGen: modules/Meshing
  xvfb xauth
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${1:-}" = fuzz ]; then
  for p in clang-14 libclang-rt-14-dev; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
fi
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo=sudo
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

if [ ! -f build/build.ninja ]; then
  cmake --preset release >&2
fi
cmake --build --preset release >&2
if ! grep -q '^ART_HAVE_MMG:INTERNAL=ON' build/CMakeCache.txt 2>/dev/null; then
  echo "setup: MMG is missing (see cmake's warning above): --refinement anisotropic will refuse to run" >&2
fi

case "${1:-}" in
  "") ;;
  demo)
    build/bin/adaptivert demo ;;
  fuzz)
    cmake --preset fuzz >&2
    cmake --build --preset fuzz >&2
    tests/fuzz/run.sh "${2:-120}" ;;
  test)
    run=()
    if [ -z "${DISPLAY:-}" ]; then run=(xvfb-run -a -s "-screen 0 1280x1024x24"); fi
    "${run[@]}" ctest --preset release ;;
  paraview)
    bash paraview/setup.sh ;;
  *)
    echo "setup: unknown action '$1' (use demo, test, fuzz or paraview)" >&2; exit 2 ;;
esac
