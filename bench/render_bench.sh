#!/usr/bin/env bash
# Render benchmarks beside the classic Python way and the encoder alone: each
# case runs vibra and its peer in turn, REPEAT=5 rounds, and prints frames/s
# of the whole process as median (min-max) and the ratio pair by pair, so a
# reader sees the machine's noise (bench/wall_time.sh); file sizes beside.
#
#   bench/render_bench.sh [FRAMES] [png|video|window|scenes|overlap|trail|compare]   (default 300 frames,
#                                             every case; installs the peers' packages first)
#   REPEAT=N (rounds, default 5), VIBRA=path (the build to time), SCENES="pendulum orbit" (the scenes case's scenes)
#
# Cases: PNG sequences (--layout fbd) of the pendulum against png_frames.py
# and of the spring-dashpot scene against spring_dashpot_frames.py; MP4 and
# WebM against funcanim_video.py and against the ffmpeg CLI encoding the same
# frames from raw YUV in memory with the same settings (the encoder's own
# ceiling); the moving window against moving_window.py; the built-in scenes
# spring_dashpot, bumpy_road, elastic_pendulum and orbit as MP4 against the
# encoder's ceiling (and the other built-in scenes at 720p); x264 alone
# beside a separate drawing process (the bound for any pipeline); the orbit's
# trail over 1e3 and 1e6 steps; a 4-run
# comparison (--compare scheme=...) against one run of the same scene, and
# one with u and phase panels against x264 alone on its frames.
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

source bench/wall_time.sh  # seconds, median, alone, pair
size() { printf "%-44s %8d KiB\n" "  file size: $(basename "$1")" $(( $(stat -c %s "$1") / 1024 )); }

# png_against LABEL PEER VIBRA_RENDER_ARGS...: PNG frames, --layout fbd, at 720p
# and 1080p, vibra against a peer script drawing the same scene.
png_against() {
  local label=$1 peer=$2; shift 2
  local args=("$@")
  for size in 720p 1080p; do
    local dims; dims=$([ $size = 720p ] && echo 1280x720 || echo 1920x1080)
    mkdir -p "$WORK/v_$size" "$WORK/p_$size"
    ours() { "$VIBRA" render "${args[@]}" --layout fbd --size "$dims" -o "$WORK/v_$size"; }
    theirs() { $PY "$PEERS/$peer" --frames "$FRAMES" --size $size --out "$WORK/p_$size"; }
    PAIR_SAYS="vibra / matplotlib" pair "$FRAMES" "vibra PNG $size $label" ours "matplotlib PNG $size ($peer)" theirs
    size "$(ls "$WORK/v_$size"/*.png | head -1)"
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

# ceiling NAME: x264 alone (or VP9 with NAME=vp9) on vibra's frames in $WORK/raw.yuv, size $dims at 30 frames/s.
ceiling() {
  local codec=("${X264[@]}") format=mp4
  [ "${1:-}" = vp9 ] && codec=("${VP9[@]}") format=webm
  ffmpeg -v error -f rawvideo -pix_fmt yuv420p -s "$dims" -r 30 -i "$WORK/raw.yuv" "${codec[@]}" -f $format -y "$WORK/ceiling.$format"
}
VP9=(-c:v libvpx-vp9 -crf 32 -b:v 0 -row-mt 1 -deadline realtime -cpu-used 8 -g 150 -threads 2)

wanted video && {
echo
echo "== Video, --layout fbd (the peers' scene), $FRAMES frames"
for size in 720p 1080p; do
  dims=$([ $size = 720p ] && echo 1280x720 || echo 1920x1080)
  "$VIBRA" render "${SCENE[@]}" --layout fbd --size "$dims" -o "$WORK/raw.yuv"
  mp4() { "$VIBRA" render "${SCENE[@]}" --layout fbd --size "$dims" -o "$WORK/v.mp4"; }
  webm() { "$VIBRA" render "${SCENE[@]}" --layout fbd --size "$dims" -o "$WORK/v.webm"; }
  x264_alone() { ceiling; }
  vp9_alone() { ceiling vp9; }
  funcanim() { $PY "$PEERS/funcanim_video.py" --frames "$FRAMES" --size $size --codec mp4 --out "$WORK/peer"; }
  PAIR_SAYS="vibra / x264 alone" pair "$FRAMES" "vibra MP4 $size (default: H.264 crf 23)" mp4 \
    "ffmpeg CLI x264 encoder only, same settings" x264_alone
  size "$WORK/v.mp4"
  PAIR_SAYS="vibra / VP9 alone" pair "$FRAMES" "vibra WebM $size (default: VP9 crf 32)" webm \
    "ffmpeg CLI VP9 encoder only, same settings" vp9_alone
  size "$WORK/v.webm"
  PAIR_SAYS="vibra / matplotlib" pair "$FRAMES" "vibra MP4 $size" mp4 "matplotlib FuncAnimation MP4 $size" funcanim
  printf "  -> file size vibra / peer = %.2fx\n" "$(echo "$(stat -c %s "$WORK/v.mp4") / $(stat -c %s "$WORK/peer.mp4")" | bc -l)"
  rm -f "$WORK"/*.mp4 "$WORK"/*.webm "$WORK/raw.yuv"
done
alone "vibra MP4 720p, default layout (fbd+plot)" "$FRAMES" "$VIBRA" render "${SCENE[@]}" --size 1280x720 -o "$WORK/v.mp4"
size "$WORK/v.mp4"
rm -f "$WORK/v.mp4"
}

wanted window && {
echo
echo "== Moving window (u against t, 4 periods), 720p, $FRAMES PNG frames"
mkdir -p "$WORK/mw_v" "$WORK/mw_p"
ours() { "$VIBRA" render pendulum "${SCENE[@]}" --layout plot --window 4periods -o "$WORK/mw_v"; }
theirs() { $PY "$PEERS/moving_window.py" --frames "$FRAMES" --size 720p --window 4 --out "$WORK/mw_p"; }
PAIR_SAYS="vibra / matplotlib" pair "$FRAMES" "vibra moving window" ours "matplotlib moving window (moving_window.py)" theirs
}

# raw_frames SIZE RENDER_ARGS...: the render's YUV frames into $WORK/raw.yuv
# (the encoder's input in ceiling); prints how many there are.
raw_frames() {
  local size=$1; shift
  "$VIBRA" render "$@" --size "$size" -q -o "$WORK/raw.yuv"
  local w=${size%x*} h=${size#*x}
  echo $(( $(stat -c %s "$WORK/raw.yuv") / (w * h * 3 / 2) ))
}

# A scene as MP4 against x264 alone on the same frames: vibra's YUV frames
# first, then the two in turn. scene_against_x264 SIZE RENDER_ARGS...
scene_against_x264() {
  dims=$1; shift  # global: ceiling encodes at this size
  local args=("$@")
  local frames; frames=$(raw_frames "$dims" "${args[@]}")
  ours() { "$VIBRA" render "${args[@]}" --size "$dims" -q -o "$WORK/v.mp4"; }
  x264_alone() { ceiling; }
  PAIR_SAYS="vibra / x264 alone (target >= ${TARGET:-0.90})" pair "$frames" "vibra MP4 $dims ${args[*]:0:1} ($frames frames)" ours \
    "ffmpeg CLI x264 encoder only, same frames" x264_alone
  rm -f "$WORK/raw.yuv" "$WORK"/*.mp4
}

wanted scenes && {
echo
echo "== Built-in scenes, MP4 (layout fbd+plot), about $FRAMES frames (periods = FRAMES/60: 60 frames a period)"
periods=$(( FRAMES / 60 > 0 ? FRAMES / 60 : 1 ))
for dims in 1280x720 1920x1080; do
  for scene in ${SCENES:-pendulum spring spring_dashpot bumpy_road washing_machine sliding_box bouncing_ball rlc elastic_pendulum orbit}; do
    scene_against_x264 "$dims" $scene --set periods=$periods
  done
done
# Slow motion: most frames fall between solver steps, each drawn as the
# still at its time.
scene_against_x264 1280x720 pendulum --set periods=$(( periods / 4 > 0 ? periods / 4 : 1 )) --speed 0.25
scene_against_x264 1280x720 spring --set periods=$periods --slow 1-2:0.2
}

# The bound no pipeline can pass on this machine: x264 alone on the frames
# while the same frames are drawn by a separate process (-o - --format y4m,
# thrown away), both started together. vibra against it says what its own
# pipeline costs; it against x264 alone, what the drawing's CPU costs x264.
wanted overlap && {
echo
echo "== Drawing beside the encoder, MP4 720p, about $FRAMES frames"
periods=$(( FRAMES / 60 > 0 ? FRAMES / 60 : 1 ))
# overlap_case SIZE RENDER_ARGS...
overlap_case() {
  dims=$1; shift  # global: ceiling encodes at this size
  local args=("$@")
  local frames; frames=$(raw_frames "$dims" "${args[@]}")
  ours() { "$VIBRA" render "${args[@]}" --size "$dims" -q -o "$WORK/v.mp4"; }
  beside() { "$VIBRA" render "${args[@]}" --size "$dims" -q -o - --format y4m >/dev/null & ceiling; wait $!; }
  x264_alone() { ceiling; }
  PAIR_SAYS="vibra / x264 beside a drawing process" pair "$frames" "vibra MP4 ${args[*]:0:1} ($frames frames)" ours \
    "x264 alone beside vibra -o - --format y4m" beside
  PAIR_SAYS="x264 beside a drawing process / x264 alone (the bound)" pair "$frames" \
    "x264 alone beside vibra -o - --format y4m" beside "ffmpeg CLI x264 encoder only, same frames" x264_alone
  rm -f "$WORK/raw.yuv" "$WORK"/*.mp4
}
for scene in ${SCENES:-spring washing_machine bumpy_road sliding_box}; do overlap_case 1280x720 $scene --set periods=$periods; done
overlap_case 1280x720 spring --set periods=$periods --compare scheme=forward-euler,backward-euler,crank-nicolson,rk4 --panels u,phase
}

wanted trail && {
echo
echo "== The orbit's trail (layout fbd: the diagram alone), 720p MP4, the same frames from 1e3 and 1e6 steps"
echo "   (the whole process: the 1e6-step run also solves a thousand times more steps, twice)"
periods=$(( FRAMES / 60 > 0 ? FRAMES / 60 : 1 ))
for steps in 1000 1000000; do
  frames=$(raw_frames 1280x720 orbit --layout fbd --set periods=$periods --set steps_per_period=$((steps / periods)))
  rm -f "$WORK/raw.yuv"
  alone "vibra orbit, $steps steps, $frames frames" "$frames" "$VIBRA" render orbit --layout fbd --set periods=$periods \
    --set steps_per_period=$((steps / periods)) -q -o "$WORK/v.mp4"
  printf "  -> %.2f ms a frame, whole process; %d KiB peak\n" "$(echo "1000 / $MEDIAN_FPS" | bc -l)" "$PEAK_KIB"
  rm -f "$WORK/v.mp4"
done
}

wanted compare && {
echo
echo "== Comparisons, MP4 720p (layout fbd+plot), about $FRAMES frames"
periods=$(( FRAMES / 60 > 0 ? FRAMES / 60 : 1 ))
SCHEMES=scheme=forward-euler,backward-euler,crank-nicolson,rk4
for scene in spring pendulum; do
  one() { "$VIBRA" render $scene --set periods=$periods -q -o "$WORK/one.mp4"; }
  four() { "$VIBRA" render $scene --set periods=$periods -q -o "$WORK/four.mp4" --compare $SCHEMES; }
  frames=$(raw_frames 1280x720 $scene --set periods=$periods)
  rm -f "$WORK/raw.yuv"
  PAIR_SAYS="4 runs / one run (target >= 0.75)" pair "$frames" "vibra $scene, 4 runs (--compare scheme=...)" four \
    "vibra $scene, one run" one
  rm -f "$WORK/one.mp4" "$WORK/four.mp4"
done
# Four schemes with u and phase panels against x264 alone on the same frames.
TARGET=0.85 scene_against_x264 1280x720 spring --set periods=$periods --compare $SCHEMES --panels u,phase
}
