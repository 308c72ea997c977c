#!/usr/bin/env bash
# render of a volume too large for its full-resolution tets (700^3 voxels: 1.7 billion tets,
# ~171 GB) stops at once with the way out, instead of being killed by the system half-way.
# The voxels are a sparse file of zeros: 343 MB read, no disk used.
set -euo pipefail
art=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
avail=$(awk '/^MemAvailable:/ { print $2 }' /proc/meminfo)
[ "${avail:-0}" -lt 150000000 ] || { echo "more than 150 GB available: nothing to refuse"; exit 77; }
printf 'ObjectType = Image\nNDims = 3\nDimSize = 700 700 700\nElementType = MET_UCHAR\nElementDataFile = big.raw\n' \
  > "$work/big.mhd"
truncate -s 343000000 "$work/big.raw"
set +e
"$art" render "$work/big.mhd" -o "$work/big.png" --size 32x32 2> "$work/err.txt"
rc=$?
set -e
rm -f "$work/big.raw"
[ "$rc" -eq 1 ] || { echo "FAIL: exit $rc: $(cat "$work/err.txt")" >&2; exit 1; }
grep -q "big.mhd: its full-resolution tets (700 x 700 x 700 voxels, 1708 million tets) need about 170.8 GB.*--tets N" \
  "$work/err.txt" || { echo "FAIL: $(cat "$work/err.txt")" >&2; exit 1; }
[ ! -e "$work/big.png" ] || { echo "FAIL: an image was written" >&2; exit 1; }
echo "refused: $(cat "$work/err.txt")"
