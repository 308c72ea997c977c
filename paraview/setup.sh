#!/usr/bin/env bash
# The ParaView plugin's set-up (cmake/setup.sh paraview runs it after the project's own build):
# installs Debian's ParaView 5.11 (paraview, paraview-dev, OpenMPI), unpacks python3-paraview into a
# private prefix (it conflicts with python3-vtk9, which the project needs), configures and builds
# the plugin in build/paraview against that prefix, and runs its tests. build/paraview/env.sh then
# puts pvbatch, pvpython and paraview on PATH with the plugin loaded.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/paraview
prefix=$build/prefix
if [ ! -x build/bin/adaptivert ]; then
  echo "setup: build the project first (bash cmake/setup.sh paraview does both)" >&2
  exit 1
fi

packages=(paraview paraview-dev openmpi-bin libopenmpi-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo=sudo; fi
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  # No recommends: they would pull python3-paraview, which removes python3-vtk9.
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

# The private prefix: python3-paraview's files (ParaView's Python, pvpython, the wrapping
# hierarchy files paraview-dev's CMake files name) beside links to what paraview and paraview-dev
# installed, and a copy of ParaView's CMake folder (a link would resolve back to /usr, where the
# Python files are not).
version=$(dpkg-query -W -f='${Version}' paraview)
if [ "$(cat "$prefix/.version" 2>/dev/null)" != "$version" ]; then
  echo "setup: making ParaView's private prefix in $prefix" >&2
  rm -rf "$prefix"
  mkdir -p "$prefix/deb"
  # apt-get download needs the package lists, which an image may have removed since paraview's install.
  if ! (cd "$prefix/deb" && apt-get download -qq "python3-paraview=$version" 2>/dev/null); then
    $sudo apt-get update -qq
    (cd "$prefix/deb" && apt-get download -qq "python3-paraview=$version") ||
      { echo "setup: cannot download python3-paraview $version (apt-get download)" >&2; exit 1; }
  fi
  dpkg-deb -x "$prefix"/deb/python3-paraview_*.deb "$prefix"
  rm -rf "$prefix/deb"
  cmakedir=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11
  dpkg-query -L paraview paraview-dev | while read -r f; do
    [ -f "$f" ] || continue
    case "$f" in "$cmakedir"/*) continue ;; esac
    [ -e "$prefix$f" ] && continue
    mkdir -p "$prefix$(dirname "$f")"
    ln -s "$f" "$prefix$f"
  done
  mkdir -p "$prefix$(dirname "$cmakedir")"
  cp -r "$cmakedir" "$prefix$cmakedir"
  echo "$version" > "$prefix/.version"
fi

if [ ! -f "$build/build.ninja" ]; then
  cmake -S paraview -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DParaView_DIR="$PWD/$prefix/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11" >&2
fi
cmake --build "$build" -- -j2 >&2

run=()
if [ -z "${DISPLAY:-}" ]; then run=(xvfb-run -a -s "-screen 0 1280x1024x24"); fi
"${run[@]}" ctest --test-dir "$build" --output-on-failure
echo "setup: source $build/env.sh for pvbatch, pvpython and paraview with the AdaptiveRT plugin" >&2
