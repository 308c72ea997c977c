#!/bin/sh
# The triangle benchmark program: TriangleGrid vs Embree 3 and VTK's locators on the four scenes,
# plus the paper's tables. Usage: tests/benchmarks/triangles.sh [BUILD_DIR] [RESULTS_DIR] [extra options]
# (e.g. --runs 5 --tri-size 800x600). Writes triangles.json, triangles.md and triangles.png.
set -e
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build}
results=${2:-bench-results}
shift 2 2>/dev/null || shift $#
exec "$build/bin/adaptivert" bench triangles --results "$results" "$@"
