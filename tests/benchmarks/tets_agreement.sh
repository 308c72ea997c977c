#!/bin/sh
# Image agreement of two builds of the tet caster: every scene below rendered by BEFORE and by
# AFTER (float TIFF, so nothing is hidden by 8-bit rounding) and compared (RMSE, PSNR). BEFORE and
# AFTER are folders holding bin/adaptivert and lib/ (a build folder, or a copy of one taken before
# a change). The meshes are reduced once by AFTER. Also checks that AFTER's image does not depend
# on the thread count (1 vs 2 threads, bit for bit).
# Usage: tests/benchmarks/tets_agreement.sh BEFORE AFTER [OUT_DIR]   (prints a markdown table)
set -e
here=$(cd "$(dirname "$0")/../.." && pwd)
before=$(cd "$1" && pwd)
after=$(cd "$2" && pwd)
out=${3:-agreement}
mkdir -p "$out/meshes" "$out/before" "$out/after"
ct128="$here/data/ct-head-128.mha"
ct256="$here/data/full/ct-head.mha"
brain="$here/data/full/mni_icbm152_t1_tal_nlin_sym_09a_converted.nii.gz"
run_after() { LD_LIBRARY_PATH="$after/lib" "$after/bin/adaptivert" "$@"; }
run_before() { LD_LIBRARY_PATH="$before/lib" "$before/bin/adaptivert" "$@"; }

m="$out/meshes"
[ -f "$m/ct128.vtu" ] || run_after reduce "$ct128" "$m/ct128.vtu" --tets 100000 --levels 10000 --tf ct-skin-bone --relocate -q
if [ -f "$ct256" ]; then
  [ -f "$m/ct256.vtu" ] || run_after reduce "$ct256" "$m/ct256.vtu" --tets 400000 --levels 25000,100000 --tf ct-skin-bone --relocate -q
fi
if [ -f "$brain" ]; then
  [ -f "$m/brain.vtu" ] || run_after reduce "$brain" "$m/brain.vtu" --tets 200000 --tf grey-ramp --relocate -q
fi

view="--azimuth 30 --elevation 10 --no-error -q"
# name|input|options
scenes=$(cat <<EOF
ct128-full-160|$ct128|--size 160x160
ct128-full|$ct128|--size 500x500
ct128-10k|$m/ct128_10000.vtu|--size 500x500 --tf ct-skin-bone
ct128-100k|$m/ct128.vtu|--size 500x500 --tf ct-skin-bone
ct128-100k-bone|$m/ct128.vtu|--size 500x500 --tf ct-bone
ct128-100k-grey|$m/ct128.vtu|--size 500x500 --tf grey-ramp
ct128-100k-iso|$m/ct128.vtu|--size 300x300 --tf ct-skin-bone --iso 300,1200 --iso-opacity 0.6
ct128-100k-mip|$m/ct128.vtu|--size 300x300 --mip
ct128-100k-trapezoid|$m/ct128.vtu|--size 300x300 --tf ct-skin-bone --integrator trapezoid
ct128-100k-no-ert|$m/ct128.vtu|--size 300x300 --tf ct-skin-bone --ert 1
ct128-100k-clip|$m/ct128.vtu|--size 300x300 --tf ct-skin-bone --clip=122,122,80,-1,0,0;0,0,60,0,0,1
ct128-100k-parallel|$m/ct128.vtu|--size 300x300 --tf ct-skin-bone --parallel
ct128-100k-inside|$m/ct128.vtu|--size 300x300 --tf grey-ramp --zoom 4
ct128-full-inside|$ct128|--size 200x200 --tf ct-skin-bone --zoom 3
ct256-25k|$m/ct256_25000.vtu|--size 500x500 --tf ct-skin-bone
ct256-100k|$m/ct256_100000.vtu|--size 500x500 --tf ct-skin-bone
ct256-400k|$m/ct256.vtu|--size 500x500 --tf ct-skin-bone
ct256-400k-bone|$m/ct256.vtu|--size 500x500 --tf ct-bone
ct256-400k-grey|$m/ct256.vtu|--size 500x500 --tf grey-ramp
brain-200k|$m/brain.vtu|--size 500x500 --tf grey-ramp
brain-200k-bone|$m/brain.vtu|--size 500x500 --tf ct-bone
box-own-points|$here/tests/data/duplicates/box-own-points.vtu|--size 48x48 --azimuth 30 --elevation 20
two-tets|$here/modules/TetRayCast/Testing/Data/two-tets.vtu|--size 64x48 --tf grey-ramp
EOF
)
echo "| scene | RMSE | PSNR dB | max abs |"
echo "|---|---:|---:|---:|"
echo "$scenes" | while IFS='|' read -r name input opts; do
  [ -f "$input" ] || continue
  # shellcheck disable=SC2086
  run_before render "$input" -o "$out/before/$name.tif" $view $opts >/dev/null
  # shellcheck disable=SC2086
  run_after render "$input" -o "$out/after/$name.tif" $view $opts >/dev/null
  run_after compare "$out/before/$name.tif" "$out/after/$name.tif" --json -q |
    /usr/bin/python3 -c "import json,sys; d=json.load(sys.stdin); p=d['psnr_db']; print('| $name | %.3g | %s | %.3g |' % (d['rmse'], 'inf' if p is None else '%.1f' % p, d['max_abs']))"
done
if [ -f "$m/ct256.vtu" ]; then
  run_after render "$m/ct256.vtu" -o "$out/after/threads-1.tif" $view --size 500x500 --tf ct-skin-bone --threads 1 >/dev/null
  run_after render "$m/ct256.vtu" -o "$out/after/threads-2.tif" $view --size 500x500 --tf ct-skin-bone --threads 2 >/dev/null
  run_after compare "$out/after/threads-1.tif" "$out/after/threads-2.tif" --json -q |
    /usr/bin/python3 -c "import json,sys; d=json.load(sys.stdin); print('| ct256-400k, 1 vs 2 threads (AFTER) | %.3g | | %.3g |' % (d['rmse'], d['max_abs']))"
fi
