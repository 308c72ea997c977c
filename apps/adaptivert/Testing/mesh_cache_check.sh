#!/usr/bin/env bash
# render --mesh-cache: the second render of a volume with the same reduction loads the mesh and
# writes the same image; other voxels, other settings or a damaged entry reduce again.
set -euo pipefail
art=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
vol=$src/data/ct-head-128.mha cache=$work/cache
render() { "$art" render "$1" -o "$work/$2.png" --size 64x64 --tets 2000 --no-error --mesh-cache "$cache" "${@:3}"; }
entries() { find "$cache" -name '*.vtu' | wc -l; }

render "$vol" first > "$work/first.txt"
grep -q "from the mesh cache" "$work/first.txt" && fail "first render came from the cache"
[ "$(entries)" -eq 1 ] || fail "first render stored $(entries) entries"
render "$vol" second > "$work/second.txt"
grep -q "from the mesh cache" "$work/second.txt" || fail "second render reduced again: $(cat "$work/second.txt")"
cmp -s "$work/first.png" "$work/second.png" || fail "the cached mesh renders another image"
# Another budget, another entry.
render "$vol" budget --tets 2500 > "$work/budget.txt"
grep -q "from the mesh cache" "$work/budget.txt" && fail "another budget came from the cache"
[ "$(entries)" -eq 2 ] || fail "another budget: $(entries) entries"
# A copy of the voxels hits; the same voxels with one changed (within their range, so the
# transfer function stays) miss. An uncompressed 20^3 volume
# (a ramp with a ball), edited in place.
{
  printf 'ObjectType = Image\nNDims = 3\nDimSize = 20 20 20\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n'
  LC_ALL=C awk 'BEGIN { for (z = 0; z < 20; z++) for (y = 0; y < 20; y++) for (x = 0; x < 20; x++) {
    v = x * 6 + ((x - 9) ^ 2 + (y - 10) ^ 2 + (z - 8) ^ 2 < 36 ? 100 : 0); printf "%c", v } }'
} > "$work/ball.mha"
cp "$work/ball.mha" "$work/ball-copy.mha"
render "$work/ball.mha" ball --tets 300 > "$work/ball.txt"
render "$work/ball-copy.mha" copy --tets 300 > "$work/copy.txt"
grep -q "from the mesh cache" "$work/copy.txt" || fail "a copy of the volume missed the cache"
printf '\x00' | dd of="$work/ball-copy.mha" bs=1 seek=$(($(stat -c %s "$work/ball.mha") - 4321)) conv=notrunc status=none
render "$work/ball-copy.mha" edited --tets 300 > "$work/edited.txt"
grep -q "from the mesh cache" "$work/edited.txt" && fail "edited voxels came from the cache"
# A damaged entry (truncated) is a miss and is written again whole.
for f in "$cache"/*.vtu; do truncate -s 1000 "$f"; done
render "$vol" damaged > "$work/damaged.txt" || fail "a damaged entry failed the render"
grep -q "from the mesh cache" "$work/damaged.txt" && fail "a damaged entry was used"
cmp -s "$work/first.png" "$work/damaged.png" || fail "the render after a damaged entry differs"
render "$vol" again > "$work/again.txt"
grep -q "from the mesh cache" "$work/again.txt" || fail "the rewritten entry was not used"
# A cache that cannot be written (its folder's parent is a file) is a note; the image is made.
"$art" render "$vol" -o "$work/nocache.png" --size 64x64 --tets 2000 --no-error --mesh-cache "$work/first.png/cache" \
  > "$work/nocache.txt" || fail "an unwritable cache failed the render"
grep -q "note .*the mesh cache was not written: .*first.png/cache: cannot create" "$work/nocache.txt" \
  || fail "unwritable cache: $(cat "$work/nocache.txt")"
cmp -s "$work/first.png" "$work/nocache.png" || fail "the render without its cache differs"
# A mesh input takes no cache: it is a usage error like the other reduction options.
"$art" render "$src/modules/TetRayCast/Testing/Data/two-tets.vtu" -o "$work/m.png" --mesh-cache "$cache" \
  2> "$work/mesh.txt" && fail "a mesh with --mesh-cache was accepted"
grep -q "does not apply to a mesh" "$work/mesh.txt" || fail "mesh input: $(cat "$work/mesh.txt")"
# An entry is a .vtu any VTK reader opens: info reads it as a tet mesh of its tets.
entry=$(ls -t "$cache"/*.vtu | head -n 1) # the one rewritten after the damage
"$art" info "$entry" > "$work/entry.txt" || fail "info cannot read a cache entry: $entry"
grep -q "vtkTetra" "$work/entry.txt" || fail "a cache entry is no tet mesh: $(cat "$work/entry.txt")"
echo "mesh cache: hits, misses on other voxels and budgets, damaged entries rewritten"
