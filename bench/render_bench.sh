#!/usr/bin/env bash
# Render benchmarks beside the classic Python way, in one run (ratios are
# stable on a shared machine; absolute times are not). Prints frames/s of the
# whole process (best of REPEAT=3 runs), peak memory and file sizes.
#
#   bench/render_bench.sh [FRAMES] [png|video|window|scenes|trail|compare]   (default 300 frames,
#                                             every case; installs the peers' packages first)
#
# Cases: PNG sequences (--layout fbd) of the pendulum against png_frames.py
# and of the spring-dashpot scene against spring_dashpot_frames.py; MP4 and
# WebM against funcanim_video.py and against the ffmpeg CLI encoding the same
# frames from raw YUV in memory with the same settings (the encoder's own
# ceiling); the moving window against moving_window.py; the built-in scenes
# spring_dashpot, bumpy_road, elastic_pendulum and orbit as MP4 against the
# encoder's ceiling (and the other built-in scenes at 720p); the orbit's
# trail over 1e3 and 1e6 steps; a 4-run
# comparison (--compare scheme=...) against one run of the same scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup --bench >/dev/null  # the peers' packages, and a current build
FRAMES=${1:-300}
ONLY=${2:-}
wanted() { [ -z "$ONLY" ] || [ "$ONLY" = "$1" ]; }
VIBRA=${VIBRA:-build/vibra}
PEERS=${PEERS:-bench/peers}
PY=/usr/bin/python3
WORK=$(mktemp -d /dev/shm/vibra_bench.XXXXXX 2>/dev/null || mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# The peers' scene: Theta = 40 deg, alpha = 0.8, dt = 2 pi/60, one frame per step.
SCENE=(--set Theta=40 --set alpha=0.8 --set "dt=2*pi/60" --set "T=$((FRAMES - 1))*2*pi/60" --set scheme=centered --frame-per-step -q)

# run NAME COMMAND...: frames/s, seconds and peak memory of the whole process,
# the fastest of REPEAT runs (default 3): a shared machine only ever slows a run down.
REPEAT=${REPEAT:-3}
run() {
  local name=$1; shift
  local start end kib best=""
  for ((i = 0; i < REPEAT; ++i)); do
    start=$(date +%s.%N)
    /usr/bin/time -f %M -o "$WORK/mem" "$@" >/dev/null 2>"$WORK/err" || { echo "$name: FAILED"; cat "$WORK/err"; return 1; }
    end=$(date +%s.%N)
    local took; took=$(echo "$end - $start" | bc -l)
    if [ -z "$best" ] || (( $(echo "$took < $best" | bc -l) )); then best=$took; fi
  done
  kib=$(tail -1 "$WORK/mem")
  LAST_FPS=$(echo "${CASE_FRAMES:-$FRAMES} / $best" | bc -l)
  LAST_KIB=$kib
  printf "%-44s %8.1f frames/s %8.2f s %8d KiB peak\n" "$name" "$LAST_FPS" "$best" "$kib"
}
size() { printf "%-44s %8d KiB\n" "  file size: $(basename "$1")" $(( $(stat -c %s "$1") / 1024 )); }
ratio() { printf "  -> vibra / peer = %.1fx\n" "$(echo "$1 / $2" | bc -l)"; }

# png_against LABEL PEER VIBRA_RENDER_ARGS...: PNG frames, --layout fbd, at 720p
# and 1080p, vibra against a peer script drawing the same scene.
png_against() {
  local label=$1 peer=$2; shift 2
  for size in 720p 1080p; do
    local dims; dims=$([ $size = 720p ] && echo 1280x720 || echo 1920x1080)
    mkdir -p "$WORK/v_$size" "$WORK/p_$size"
    run "vibra PNG $size $label" "$VIBRA" render "$@" --layout fbd --size "$dims" -o "$WORK/v_$size"; local ours=$LAST_FPS
    run "matplotlib PNG $size ($peer)" $PY "$PEERS/$peer" --frames "$FRAMES" --size $size --out "$WORK/p_$size"
    ratio "$ours" "$LAST_FPS"
    rm -rf "$WORK/v_$size" "$WORK/p_$size"
  done
}

wanted png && {
echo "== PNG frames, --layout fbd, $FRAMES frames"
png_against pendulum png_frames.py "${SCENE[@]}"
# The spring-dashpot scene (Fig 1.18), one frame per step of dt = 2 pi/60.
png_against spring_dashpot spring_dashpot_frames.py spring_dashpot --set "dt=2*pi/60" \
  --set "T=$((FRAMES - 1))*2*pi/60" --frame-per-step -q
}

# The encoders' ceiling: ffmpeg encodes vibra's own YUV frames (-o x.yuv),
# already in memory, with the settings vibra uses by default.
X264=(-c:v libx264 -preset veryfast -x264-params bframes=0:me=dia:subme=1:8x8dct=0 -crf 23 -g 150 -profile:v high -threads 2)

wanted video && {
VP9=(-c:v libvpx-vp9 -crf 32 -b:v 0 -row-mt 1 -deadline realtime -cpu-used 8 -g 150 -threads 2)
echo
echo "== Video, --layout fbd (the peers' scene), $FRAMES frames"
for size in 720p 1080p; do
  dims=$([ $size = 720p ] && echo 1280x720 || echo 1920x1080)
  "$VIBRA" render "${SCENE[@]}" --layout fbd --size "$dims" -o "$WORK/raw.yuv"
  run "vibra MP4 $size (default: H.264 crf 23)" "$VIBRA" render "${SCENE[@]}" --layout fbd --size "$dims" -o "$WORK/v.mp4"; mp4=$LAST_FPS
  size "$WORK/v.mp4"; mp4_size=$(stat -c %s "$WORK/v.mp4")
  run "ffmpeg CLI x264 encoder only, same settings" ffmpeg -v error -f rawvideo -pix_fmt yuv420p -s "$dims" -r 30 \
    -i "$WORK/raw.yuv" "${X264[@]}" -f mp4 -y "$WORK/ceiling.mp4"
  printf "  -> vibra's whole pipeline reaches %.0f%% of the encoder alone\n" "$(echo "100 * $mp4 / $LAST_FPS" | bc -l)"
  run "vibra WebM $size (default: VP9 crf 32)" "$VIBRA" render "${SCENE[@]}" --layout fbd --size "$dims" -o "$WORK/v.webm"; webm=$LAST_FPS
  size "$WORK/v.webm"
  run "ffmpeg CLI VP9 encoder only, same settings" ffmpeg -v error -f rawvideo -pix_fmt yuv420p -s "$dims" -r 30 \
    -i "$WORK/raw.yuv" "${VP9[@]}" -f webm -y "$WORK/ceiling.webm"
  printf "  -> vibra's whole pipeline reaches %.0f%% of the encoder alone\n" "$(echo "100 * $webm / $LAST_FPS" | bc -l)"
  run "matplotlib FuncAnimation MP4 $size" $PY "$PEERS/funcanim_video.py" --frames "$FRAMES" --size $size --codec mp4 --out "$WORK/peer"
  size "$WORK/peer.mp4"
  ratio "$mp4" "$LAST_FPS"
  printf "  -> file size vibra / peer = %.2fx\n" "$(echo "$mp4_size / $(stat -c %s "$WORK/peer.mp4")" | bc -l)"
  rm -f "$WORK"/*.mp4 "$WORK"/*.webm "$WORK/raw.yuv"
done
run "vibra MP4 720p, default layout (fbd+plot)" "$VIBRA" render "${SCENE[@]}" --size 1280x720 -o "$WORK/v.mp4"
size "$WORK/v.mp4"
rm -f "$WORK/v.mp4"
}

wanted window && {
echo
echo "== Moving window (u against t, 4 periods), 720p, $FRAMES PNG frames"
mkdir -p "$WORK/mw_v" "$WORK/mw_p"
run "vibra moving window" "$VIBRA" render pendulum "${SCENE[@]}" --layout plot --window 4periods -o "$WORK/mw_v"; ours=$LAST_FPS
run "matplotlib moving window (moving_window.py)" $PY "$PEERS/moving_window.py" --frames "$FRAMES" --size 720p --window 4 --out "$WORK/mw_p"
ratio "$ours" "$LAST_FPS"
}

# A built-in scene as MP4 (its own layout, fbd+plot) against x264 alone on
# the same frames: vibra's YUV frames first, then both timed.
# scene_against_x264 SCENE SIZE [--set ...]
scene_against_x264() {
  local scene=$1 dims=$2; shift 2
  "$VIBRA" render "$scene" "$@" --size "$dims" -q -o "$WORK/raw.yuv"
  local w=${dims%x*} h=${dims#*x}
  CASE_FRAMES=$(( $(stat -c %s "$WORK/raw.yuv") / (w * h * 3 / 2) ))
  run "vibra MP4 $dims $scene ($CASE_FRAMES frames)" "$VIBRA" render "$scene" "$@" --size "$dims" -q -o "$WORK/v.mp4"; local mp4=$LAST_FPS
  run "ffmpeg CLI x264 encoder only, same frames" ffmpeg -v error -f rawvideo -pix_fmt yuv420p -s "$dims" -r 30 \
    -i "$WORK/raw.yuv" "${X264[@]}" -f mp4 -y "$WORK/ceiling.mp4"
  printf "  -> vibra's whole pipeline reaches %.0f%% of the encoder alone\n" "$(echo "100 * $mp4 / $LAST_FPS" | bc -l)"
  rm -f "$WORK/raw.yuv" "$WORK"/*.mp4
  unset CASE_FRAMES
}

wanted scenes && {
echo
echo "== Built-in scenes, MP4 (layout fbd+plot), about $FRAMES frames (periods = FRAMES/60: 60 frames a period)"
periods=$(( FRAMES / 60 > 0 ? FRAMES / 60 : 1 ))
for dims in 1280x720 1920x1080; do
  scene_against_x264 spring_dashpot "$dims" --set periods=$periods
  scene_against_x264 bumpy_road "$dims" --set periods=$periods
done
scene_against_x264 elastic_pendulum 1280x720 --set periods=$periods
scene_against_x264 orbit 1280x720 --set periods=$periods
for scene in pendulum spring washing_machine sliding_box bouncing_ball rlc; do  # the rest, at 720p
  scene_against_x264 $scene 1280x720 --set periods=$periods
done
# Slow motion: most frames fall between solver steps, each drawn as the
# still at its time.
scene_against_x264 pendulum 1280x720 --set periods=$(( periods / 4 > 0 ? periods / 4 : 1 )) --speed 0.25
scene_against_x264 spring 1280x720 --set periods=$periods --slow 1-2:0.2
}

wanted trail && {
echo
echo "== The orbit's trail (layout fbd: the diagram alone), 720p MP4, the same frames from 1e3 and 1e6 steps"
echo "   (the whole process: the 1e6-step run also solves a thousand times more steps, twice)"
periods=$(( FRAMES / 60 > 0 ? FRAMES / 60 : 1 ))
for steps in 1000 1000000; do
  "$VIBRA" render orbit --layout fbd --set periods=$periods --set steps_per_period=$((steps / periods)) -q -o "$WORK/raw.yuv"
  CASE_FRAMES=$(( $(stat -c %s "$WORK/raw.yuv") / (1280 * 720 * 3 / 2) ))
  rm -f "$WORK/raw.yuv"
  run "vibra orbit, $steps steps, $CASE_FRAMES frames" "$VIBRA" render orbit --layout fbd --set periods=$periods \
    --set steps_per_period=$((steps / periods)) -q -o "$WORK/v.mp4"
  printf "  -> %.2f ms a frame, whole process; %d KiB peak\n" "$(echo "1000 / $LAST_FPS" | bc -l)" "$LAST_KIB"
  unset CASE_FRAMES
  rm -f "$WORK/v.mp4"
done
}

wanted compare && {
echo
echo "== A 4-run comparison against one run, MP4 720p (layout fbd+plot), about $FRAMES frames"
periods=$(( FRAMES / 60 > 0 ? FRAMES / 60 : 1 ))
for scene in spring pendulum; do
  run "vibra $scene, one run" "$VIBRA" render $scene --set periods=$periods -q -o "$WORK/one.mp4"; one=$LAST_FPS
  run "vibra $scene, 4 runs (--compare scheme=...)" "$VIBRA" render $scene --set periods=$periods -q -o "$WORK/four.mp4" \
    --compare scheme=forward-euler,backward-euler,crank-nicolson,rk4
  printf "  -> 4 runs at %.0f%% of one run's frames/s (target >= 75%%)\n" "$(echo "100 * $LAST_FPS / $one" | bc -l)"
  rm -f "$WORK/one.mp4" "$WORK/four.mp4"
done
}
