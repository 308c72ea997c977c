#!/usr/bin/env bash
# reduce of a volume whose reduction does not fit in the memory available stops at once with the
# way out, names the file and its voxels and writes no mesh, instead of being killed by the system
# half-way. A 650^3 sparse volume of zeros (275 MB read, no disk used) weighted by --tf needs about
# 7.7 GB more (28 bytes a voxel for the opacity weights); the process is capped at 8 GB of address
# space, which TetReducer's check sees as the memory available, less the 1.4 GB of the volume and
# its samples (a missing check: 'out of memory').
set -euo pipefail
art=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
printf 'ObjectType = Image\nNDims = 3\nDimSize = 650 650 650\nElementType = MET_UCHAR\nElementDataFile = big.raw\n' \
  > "$work/big.mhd"
truncate -s 274625000 "$work/big.raw"
set +e
(ulimit -v 8000000; "$art" reduce "$work/big.mhd" -o "$work/big.vtu" --tets 1000 --tf ct-skin-bone 2> "$work/err.txt")
rc=$?
set -e
rm -f "$work/big.raw"
[ "$rc" -eq 1 ] || { echo "FAIL: exit $rc: $(cat "$work/err.txt")" >&2; exit 1; }
grep -q "big.mhd: reducing this volume of 650 x 650 x 650 = 274625000 voxels weighted by a transfer function's opacity needs about 7.69 GB more, more than the .* GB of memory available; crop or resample it first" \
  "$work/err.txt" || { echo "FAIL: $(cat "$work/err.txt")" >&2; exit 1; }
[ ! -e "$work/big.vtu" ] || { echo "FAIL: a mesh was written" >&2; exit 1; }
echo "refused: $(cat "$work/err.txt")"
