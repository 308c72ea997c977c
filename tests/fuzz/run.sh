#!/usr/bin/env bash
# Runs every fuzzing target (or those named) for SECONDS each over a seed corpus of the files the
# tests use, keeping what each finds under build-fuzz/findings/<format>/.
#   tests/fuzz/run.sh [SECONDS] [FORMAT...]     (after cmake --preset fuzz && cmake --build --preset fuzz)
set -uo pipefail
cd "$(dirname "$(readlink -f "$0")")/../.."
seconds=${1:-120}
shift || true
bin=build-fuzz/bin
formats=("$@")
[ ${#formats[@]} -gt 0 ] || formats=($(cd "$bin" && ls fuzz_* | sed 's/^fuzz_//'))
for f in "${formats[@]}"; do
  seeds=build-fuzz/seeds/$f found=build-fuzz/findings/$f
  mkdir -p "$seeds" "$found"
  # Seeds: every file of that format in the tests' data and what the tests wrote (under 1 MB).
  if [ "$f" = dicom ]; then
    find tests/data -name '*.dcm' -size -1024k -exec cp -n {} "$seeds/" \;
  else
    find tests/data data build/Testing/Temporary -maxdepth 4 -type f -iname "*.$f" -size -1024k \
      -exec cp -n {} "$seeds/" \; 2> /dev/null
  fi
  [ -n "$(ls -A "$seeds")" ] || printf 'x' > "$seeds/empty"
  mkdir -p "build-fuzz/corpus-$f"
  echo "== $f: $(ls "$seeds" | wc -l) seeds, ${seconds} s" >&2
  ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1 \
    "$bin/fuzz_$f" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=3072 -malloc_limit_mb=2048 \
    -max_len=262144 -artifact_prefix="$found/" -print_final_stats=1 "build-fuzz/corpus-$f" "$seeds" \
    > "$found/log.txt" 2>&1
  grep -E "^stat::number_of_executed_units|^#[0-9]+ +DONE|ERROR|SUMMARY|crash-|timeout-|oom-" "$found/log.txt" | tail -5 >&2
done
