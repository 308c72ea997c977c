#!/bin/sh
# The scaling table of `adaptivert bench tets`: the CT head at 128 and 256 (full), the full CT
# resampled x2 (a 512-class volume, labelled so) and the MNI brain; per volume FixedPoint's time
# and PSNR and the smallest reduced mesh reaching that PSNR (tets.md, "At FixedPoint's PSNR"),
# then one table and one chart over all four (tets_scaling_chart.py). Run under xvfb-run -a.
# Usage: tests/benchmarks/tets_scaling.sh ADAPTIVERT OUT_DIR [EXTRA bench OPTIONS...]
#   e.g. --tets-meshes a.vtu,b.vtu --tets-series anisotropic adds another reducer's series.
set -e
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=$1
out=$2
shift 2
runs=${RUNS:-5}
bench() { name=$1; shift; "$bin" bench tets --results "$out/$name" --runs "$runs" --tets-main-only "$@"; }
[ -n "$ONLY" ] || ONLY="ct128 ct256 brain ct512"
for v in $ONLY; do
  case $v in
  ct128) bench ct128 --tets-input "$here/data/ct-head-128.mha" --tets-levels 25000,100000,400000,1000000 "$@" ;;
  ct256) bench ct256 --tets-input "$here/data/full/ct-head.mha" --tets-levels 100000,400000,1000000,2000000 "$@" ;;
  brain) bench brain --tets-input "$here/data/full/mni_icbm152_t1_tal_nlin_sym_09a_converted.nii.gz" \
    --tets-tf grey-ramp --tets-levels 50000,200000,800000,2000000 "$@" ;;
  ct512) bench ct512 --tets-input "$here/data/full/ct-head.mha" --tets-resample 2 --tets-no-full \
    --tets-bunyk-max 2000000 --tets-levels 400000,1000000,2000000,4000000 "$@" ;;
  esac
done
/usr/bin/python3 "$here/tests/benchmarks/tets_scaling_chart.py" "$out"
