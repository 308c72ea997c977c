#!/usr/bin/env bash
# render of a volume whose full-resolution tets do not fit in the memory available (450^3 voxels:
# 453 million tets, ~72 GB; under TetMesh's limit of 2^29 tets, so it is the memory check of
# TetMesh::CheckFullResolutionFits that refuses) stops at once with the way out, names the file
# and writes no image, instead of being killed by the system half-way. The voxels are a sparse
# file of zeros: 91 MB read, no disk used. The process is capped at 8 GB of address space, which
# the check sees as the memory available (art::AvailableMemoryBytes), so a missing check fails
# fast ("out of memory") instead of swapping.
set -euo pipefail
art=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
printf 'ObjectType = Image\nNDims = 3\nDimSize = 450 450 450\nElementType = MET_UCHAR\nElementDataFile = big.raw\n' \
  > "$work/big.mhd"
truncate -s 91125000 "$work/big.raw"
set +e
(ulimit -v 8000000; "$art" render "$work/big.mhd" -o "$work/big.png" --size 32x32 2> "$work/err.txt")
rc=$?
set -e
rm -f "$work/big.raw"
[ "$rc" -eq 1 ] || { echo "FAIL: exit $rc: $(cat "$work/err.txt")" >&2; exit 1; }
grep -q "big.mhd: full-resolution tets of this volume (452594245) need about 72.4 GB, more than the .* GB of memory available; reduce it first (--tets N" \
  "$work/err.txt" || { echo "FAIL: $(cat "$work/err.txt")" >&2; exit 1; }
[ ! -e "$work/big.png" ] || { echo "FAIL: an image was written" >&2; exit 1; }
echo "refused: $(cat "$work/err.txt")"
