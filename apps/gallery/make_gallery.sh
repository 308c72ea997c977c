#!/usr/bin/env bash
# Regenerates the README's gallery: every image is rendered by adaptivert from real data.
#   apps/gallery/make_gallery.sh [BUILD_DIR]   (default build/)
# The bunny and the oa_minia level come from data/full (data/fetch) or ../shared/data.
set -euo pipefail
cd "$(dirname "$0")/../.."
art=${1:-build}/bin/adaptivert
out=apps/gallery
find_data() { for d in data/full ../shared/data; do [ -f "$d/$1" ] && { echo "$d/$1"; return; }; done; echo ""; }
run() { echo "+ adaptivert $*" >&2; "$art" "$@" --quiet; }

head=data/ct-head-128.mha
run render "$head" --reference -o $out/ct-head-reference.png --size 320x320 --zoom 1.4 --azimuth 25 --elevation 10
run render "$head" --tets 150000 -o $out/ct-head-150k-tets.png --size 320x320 --zoom 1.4 --azimuth 25 --elevation 10 --no-error
run render "$head" --tets 150000 --iso 300 --tf ct-bone -o $out/ct-head-iso.png --size 320x320 --zoom 1.4 --azimuth 25 --elevation 10 --no-error
run render "$head" --tets 150000 --mip --tf $out/mip.tf -o $out/ct-head-mip.png --size 320x320 --zoom 1.4 --azimuth 25 --elevation 10 --no-error
run render "$head" --tets 150000 --clip 122,122,80,-1,0,0 -o $out/ct-head-cutaway.png --size 320x320 --zoom 1.4 --azimuth -65 --elevation 10 --no-error
run render data/am_underworks.ply -o $out/underworks.png --size 400x300 \
  --camera-position 640,640,-545 --focal-point 1500,640,-600 --view-angle 70
run render data/am_underworks.ply -o $out/underworks-transparent.png --size 400x300 --opacity 0.5 \
  --camera-position 640,640,-545 --focal-point 1500,640,-600 --view-angle 70
bunny=$(find_data bunny.ply)
[ -n "$bunny" ] && run render "$bunny" -o $out/bunny.png --size 320x320 --zoom 1.4 --azimuth 20
echo "gallery written to $out/" >&2
