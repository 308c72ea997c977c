#!/usr/bin/env bash
# End-to-end checks of `adaptivert batch` on a small real job (3 cameras x 2 settings plus a
# reference per camera = 9 frames):
#  1. a batch killed mid-way leaves no render running, resumes and finishes, losing no frame;
#  2. two processes sharing the job render every frame exactly once;
#  3. the CSV has a row per frame with time and PSNR, and the chart is a PNG.
set -euo pipefail
art=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work/a" "$work/b"
fail() { echo "FAIL: $*" >&2; exit 1; }
results() { { find "$1" -maxdepth 1 -name '*.result.json' 2>/dev/null || true; } | wc -l; }
for d in a b; do
  # The job's paths are relative to the job file (tests/jobs/, as the README runs it); the
  # copy two folders deeper points at the source tree's data instead.
  mkdir -p "$work/$d/x/y" && cp "$src/tests/jobs/orbit_small.json" "$work/$d/x/y/job.json"
  sed -i "s|\.\./\.\./data/|$src/data/|" "$work/$d/x/y/job.json"
done
# The README's `adaptivert batch tests/jobs/orbit_small.json` (from the source tree) needs the
# job's data set where the job file points: it pointed one folder too far up, and every frame
# failed with "no such file or directory".
ds=$(sed -n 's|.*"datasets": *\["\([^"]*\)".*|\1|p' "$src/tests/jobs/orbit_small.json")
[ -f "$src/tests/jobs/$ds" ] || fail "orbit_small.json's data set $ds is not there from tests/jobs/"

# 1. Kill the batch once the first frames are finished, then resume.
job=$work/a/x/y/job.json out=$work/a/x/y/frames
"$art" batch --quiet "$job" > "$work/a/first.txt" 2>&1 &
pid=$!
for _ in $(seq 600); do
  n=$(results "$out")
  [ "$n" -ge 2 ] && break
  sleep 0.1
done
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
# The killed batch takes the frame it was rendering with it (its render child kept running).
for _ in $(seq 20); do
  pgrep -f -- "render .* -o $out/" > /dev/null || break
  sleep 0.1
done
if pgrep -f -- "render .* -o $out/" > /dev/null; then
  fail "a render of the killed batch is still running: $(pgrep -af -- "render .* -o $out/")"
fi
kept=$(results "$out"); echo "after kill: $kept results at $(date +%T)" >&2
[ "$kept" -ge 2 ] || fail "no frame finished before the kill"
for r in "$out"/*.result.json; do
  [ -s "${r%.result.json}.png" ] || fail "finished frame without its image: $r"
done
"$art" batch --quiet "$job" > "$work/a/second.txt" || fail "resumed batch failed: $(cat "$work/a/second.txt")"
grep -q "tasks        9 (" "$work/a/second.txt" || fail "unexpected summary: $(cat "$work/a/second.txt")"
now=$(sed -n 's/.*(\([0-9]*\) rendered now.*/\1/p' "$work/a/second.txt")
[ $((now + kept)) -le 10 ] || fail "resume re-rendered finished frames: $kept kept, $now rendered now"
[ "$(results "$out")" -eq 9 ] || fail "not every frame finished"
[ -z "$(find "$out" -name '.*tmp*')" ] || fail "temporary files left behind"

# 2. Two processes on one job.
job=$work/b/x/y/job.json out=$work/b/x/y/frames
"$art" batch --quiet "$job" > "$work/b/p1.txt" &
p1=$!
"$art" batch --quiet "$job" > "$work/b/p2.txt"
wait "$p1"
n1=$(sed -n 's/.*(\([0-9]*\) rendered now.*/\1/p' "$work/b/p1.txt")
n2=$(sed -n 's/.*(\([0-9]*\) rendered now.*/\1/p' "$work/b/p2.txt")
[ $((n1 + n2)) -eq 9 ] || fail "frames rendered $n1 + $n2 times, expected 9 in all"

# 3. The CSV and the chart.
csv=$out/results.csv
[ "$(grep -c ',ok,' "$csv")" -eq 9 ] || fail "CSV rows not all ok: $(cat "$csv")"
# The 6 non-reference frames carry a PSNR between 10 and 80 dB.
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "psnr_db") p = i; next }
  $1 !~ /reference/ { if (!p || $p < 10 || $p > 80) bad = 1; n++ } END { exit (bad || n != 6) }' "$csv" \
  || fail "PSNR missing or implausible: $(cat "$csv")"
head -c 8 "$out/speed_accuracy.png" | od -c | grep -q "P   N   G" || fail "chart is not a PNG"
# 4. The 6 reduced frames (3 cameras x 2 budgets) reduced the volume once per budget.
[ "$(find "$out/mesh-cache" -name '*.vtu' | wc -l)" -eq 2 ] || fail "mesh cache: $(ls "$out/mesh-cache")"
echo "batch: resume, sharing and results all correct ($kept kept, $now rendered after the kill; $n1 + $n2 shared)"
