#!/usr/bin/env bash
# A command given a volume too large for the memory available must stop at once with exit 1 and
# one message (checked against a pattern) and write nothing, instead of being killed by the
# system half-way. The volume is a sparse MetaImage of zeros (no disk used) at WORK/big.mhd; the
# command runs capped at 8 GB of address space, which art::AvailableMemoryBytes sees as the memory
# available, so a missing check fails fast ('out of memory') instead of swapping.
#   memory_refusal_check.sh WORK 'NX NY NZ' MET_TYPE RAW_BYTES PATTERN NO_OUTPUT|- -- COMMAND...
set -euo pipefail
work=$1 dims=$2 type=$3 bytes=$4 pattern=$5 output=$6
shift 6
[ "$1" = "--" ] && shift
rm -rf "$work" && mkdir -p "$work"
printf 'ObjectType = Image\nNDims = 3\nDimSize = %s\nElementType = %s\nElementDataFile = big.raw\n' "$dims" "$type" \
  > "$work/big.mhd"
truncate -s "$bytes" "$work/big.raw"
set +e
(ulimit -v 8000000; "$@" 2> "$work/err.txt")
rc=$?
set -e
rm -f "$work/big.raw"
[ "$rc" -eq 1 ] || { echo "FAIL: exit $rc: $(cat "$work/err.txt")" >&2; exit 1; }
grep -q "$pattern" "$work/err.txt" || { echo "FAIL: $(cat "$work/err.txt")" >&2; exit 1; }
[ "$output" = "-" ] || [ ! -e "$output" ] || { echo "FAIL: $output was written" >&2; exit 1; }
echo "refused: $(cat "$work/err.txt")"
