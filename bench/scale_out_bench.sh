#!/usr/bin/env bash
# Segments against one process on this machine, and the cost of joining them.
# Prints the wall time (best of REPEAT=3 runs) of
#   - one process rendering the whole video,
#   - N segments rendered by GNU parallel (-j = cores), for N = 2 and 4,
#     then joined by vibra concat,
#   - vibra concat alone, as a share of the one-process render (it copies
#     packets, so it should be I/O-bound: well under 1%).
#
#   bench/scale_out_bench.sh [FRAMES] [SIZE]   (default 600 frames at 1280x720, MP4)
set -euo pipefail
cd "$(dirname "$0")/.."
FRAMES=${1:-600}
SIZE=${2:-1280x720}
VIBRA=${VIBRA:-build/vibra}
REPEAT=${REPEAT:-3}
CORES=$(nproc)
command -v parallel >/dev/null || { echo "GNU parallel is missing: run scripts/setup"; exit 1; }
WORK=$(mktemp -d /dev/shm/vibra_scale.XXXXXX 2>/dev/null || mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# The pendulum with its plots, one frame per solver step: exactly FRAMES frames.
SCENE=(--set Theta=40 --set alpha=0.8 --set "dt=2*pi/60" --set "T=$((FRAMES - 1))*2*pi/60" --frame-per-step
       --size "$SIZE" -q)

# best COMMAND...: the fastest of REPEAT runs, in seconds (a shared machine only slows runs down).
best() {
  local fastest="" start took
  for ((i = 0; i < REPEAT; ++i)); do
    rm -rf "$WORK/parts" "$WORK"/*.mp4 && mkdir -p "$WORK/parts"
    start=$(date +%s.%N)
    "$@" >/dev/null 2>"$WORK/err" || { echo "FAILED: $*"; cat "$WORK/err"; exit 1; }
    took=$(echo "$(date +%s.%N) - $start" | bc -l)
    if [ -z "$fastest" ] || (( $(echo "$took < $fastest" | bc -l) )); then fastest=$took; fi
  done
  echo "$fastest"
}

segments_then_concat() {  # N [render options]
  local n=$1; shift
  parallel -j "$CORES" --halt now,fail=1 "$VIBRA" render "${SCENE[@]}" "$@" --segment {}/"$n" -o "$WORK/parts/v.mp4" \
    ::: $(seq 0 $((n - 1)))
  "$VIBRA" concat -q "$WORK"/parts/v.seg-*-of-"$n".mp4 -o "$WORK/joined.mp4"
}

echo "== $FRAMES frames at $SIZE, H.264 MP4 (default quality), $CORES cores"
one=$(best "$VIBRA" render "${SCENE[@]}" -o "$WORK/one.mp4")
printf "%-46s %8.2f s %8.1f frames/s\n" "one process" "$one" "$(echo "$FRAMES / $one" | bc -l)"
# vibra already spreads drawing, conversion and encoding over threads; with
# --threads 1 each segment process is single-threaded and parallel fills the cores.
for threads in "" 1; do
  for n in 2 4; do
    t=$(best segments_then_concat "$n" ${threads:+--threads $threads})
    printf "%-46s %8.2f s %8.1f frames/s  (%.2fx one process)\n" \
      "$n segments${threads:+ (--threads $threads)} by parallel, then concat" "$t" \
      "$(echo "$FRAMES / $t" | bc -l)" "$(echo "$one / $t" | bc -l)"
  done
done

# The join alone: parts made once, concat timed REPEAT times.
rm -rf "$WORK/parts" && mkdir -p "$WORK/parts"
parallel -j "$CORES" "$VIBRA" render "${SCENE[@]}" --segment {}/4 -o "$WORK/parts/v.mp4" ::: 0 1 2 3
fastest=""
for ((i = 0; i < REPEAT; ++i)); do
  rm -f "$WORK/joined.mp4"
  start=$(date +%s.%N)
  "$VIBRA" concat -q "$WORK"/parts/v.seg-*-of-4.mp4 -o "$WORK/joined.mp4"
  took=$(echo "$(date +%s.%N) - $start" | bc -l)
  if [ -z "$fastest" ] || (( $(echo "$took < $fastest" | bc -l) )); then fastest=$took; fi
done
# What any vibra command costs to start (loading Cairo, Pango, FFmpeg): not the join's work.
startup=""
for ((i = 0; i < REPEAT; ++i)); do
  start=$(date +%s.%N)
  "$VIBRA" --help >/dev/null
  took=$(echo "$(date +%s.%N) - $start" | bc -l)
  if [ -z "$startup" ] || (( $(echo "$took < $startup" | bc -l) )); then startup=$took; fi
done
printf "%-46s %8.3f s  = %.2f%% of the one-process render (%d KiB joined)\n" "concat of 4 segments" "$fastest" \
  "$(echo "100 * $fastest / $one" | bc -l)" $(( $(stat -c %s "$WORK/joined.mp4") / 1024 ))
printf "%-46s %8.3f s  = %.2f%% (process start-up %.3f s left out)\n" "  the join's own work" \
  "$(echo "$fastest - $startup" | bc -l)" "$(echo "100 * ($fastest - $startup) / $one" | bc -l)" "$startup"
