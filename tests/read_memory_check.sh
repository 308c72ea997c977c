#!/usr/bin/env bash
# A volume whose voxels do not fit in the memory available is refused from its header, before the
# read: info of a 3000^3 16-bit MetaImage (54 GB, a sparse file: no disk used) names its size, the
# memory available and the way out. The process is capped at 8 GB of address space, which the
# check sees as the memory available; without the check the read ran out ('out of memory while
# reading it'), and without a cap, where the kernel lends the allocation, it was killed half-way.
set -euo pipefail
art=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
printf 'ObjectType = Image\nNDims = 3\nDimSize = 3000 3000 3000\nElementType = MET_USHORT\nElementDataFile = big.raw\n' \
  > "$work/big.mhd"
truncate -s 54000000000 "$work/big.raw"
set +e
(ulimit -v 8000000; "$art" info "$work/big.mhd" 2> "$work/err.txt")
rc=$?
set -e
rm -f "$work/big.raw"
[ "$rc" -eq 1 ] || { echo "FAIL: exit $rc: $(cat "$work/err.txt")" >&2; exit 1; }
grep -q "big.mhd: holding its 3000 x 3000 x 3000 voxels needs about 54 GB, more than the .* GB of memory available; crop or downsample it first" \
  "$work/err.txt" || { echo "FAIL: $(cat "$work/err.txt")" >&2; exit 1; }
echo "refused: $(cat "$work/err.txt")"
