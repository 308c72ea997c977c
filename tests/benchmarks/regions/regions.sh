#!/bin/sh
# Region reductions against whole-box reductions of equal error inside the region: the CT head's
# bone (300:3000 HU) and skin-and-inside (-500:3000 HU), the MNI brain (30:255). For each: the
# region mesh (reduce --region, its JSON with the whole-box tets of equal RMS inside the region),
# time and peak memory (/usr/bin/time), then both meshes rendered with a transfer function that
# shows only the region, against the voxel reference (render --error VOLUME --json).
# Usage: tests/benchmarks/regions/regions.sh [BUILD_DIR] [RESULTS_DIR] [--render-only]
set -e
here=$(cd "$(dirname "$0")/../../.." && pwd)
build=${1:-$here/build}
out=${2:-$here/build/regions-results}
art="$build/bin/adaptivert"
mkdir -p "$out"
run() { # name volume lo hi tets
  name=$1 vol=$2 lo=$3 hi=$4 tets=$5
  /usr/bin/time -f '{"peak_rss_kb":%M,"wall_s":%e,"user_s":%U}' -o "$out/$name-time.json" \
    "$art" reduce "$vol" "$out/$name-region.vtu" --region "$lo:$hi" --tets "$tets" --json --quiet > "$out/$name-region.json"
  box=$(/usr/bin/python3 -c "import json;print(json.load(open('$out/$name-region.json'))['whole_box_tets'])")
  /usr/bin/time -f '{"peak_rss_kb":%M,"wall_s":%e,"user_s":%U}' -o "$out/$name-box-time.json" \
    "$art" reduce "$vol" "$out/$name-box.vtu" --tets "$box" --json --quiet > "$out/$name-box.json"
  # Only the region shows: clear below lo, a ramp to half opacity per unit distance over it.
  below=$(/usr/bin/python3 -c "print($lo - 0.01 * ($hi - $lo))")
  printf -- '-1e9 0 0 0 0\n%s 0 0 0 0\n%s 0.9 0.8 0.7 0.05\n%s 1 1 1 0.5\n' "$below" "$lo" "$hi" > "$out/$name-tf.txt"
  render "$name" "$vol"
}
render() { # name volume: each mesh framed as render frames it, against the voxel reference in that view
  name=$1 vol=$2
  for m in region box; do
    xvfb-run -a -s "-screen 0 1280x1024x24" "$art" render "$out/$name-$m.vtu" -o "$out/$name-$m.png" \
      --size 400x400 --azimuth 30 --elevation 10 --tf "$out/$name-tf.txt" --error "$vol" --json --quiet > "$out/$name-$m-render.json"
  done
}
if [ "$3" = "--render-only" ]; then
  render ct-bone "$here/data/ct-head-128.mha"
  render ct-skin "$here/data/ct-head-128.mha"
  /usr/bin/python3 "$(dirname "$0")/regions_table.py" "$out"
  exit 0
fi
run ct-bone "$here/data/ct-head-128.mha" 300 3000 20000
run ct-skin "$here/data/ct-head-128.mha" -500 3000 20000
if [ -f "$here/data/full/mni_icbm152_t1_tal_nlin_sym_09a_converted.nii.gz" ]; then
  run mni-brain "$here/data/full/mni_icbm152_t1_tal_nlin_sym_09a_converted.nii.gz" 30 255 50000
fi
/usr/bin/python3 "$(dirname "$0")/regions_table.py" "$out"
