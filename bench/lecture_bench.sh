#!/usr/bin/env bash
# A storyboard rendered as a whole process: its wall time as a median of
# REPEAT runs with the range, how many times faster than real time it is,
# and, when its frames fit in memory (under 4 GiB of raw YUV), against x264
# alone encoding the same frames with vibra's settings, the two in turn so
# that a busy moment slows both alike (bench/wall_time.sh).
#
#   bench/lecture_bench.sh [STORYBOARD] [WxH] [LECTURE OPTIONS...]   (default examples/damped_pendulum_lecture.toml, 1280x720)
#   bench/lecture_bench.sh bench/ten_minute_lecture.toml 1920x1080   # the 10x-real-time case: <= 60 s
#   bench/lecture_bench.sh bench/ten_minute_lecture.toml 1920x1080 --preset ultrafast   # x264's cheapest setting
set -euo pipefail
cd "$(dirname "$0")/.."
STORY=${1:-examples/damped_pendulum_lecture.toml}
DIMS=${2:-1280x720}
shift $(( $# < 2 ? $# : 2 ))
OPTIONS=("$@")  # more `vibra lecture` options, e.g. --preset ultrafast
VIBRA=${VIBRA:-build/vibra}
REPEAT=${REPEAT:-5}
WORK=$(mktemp -d /dev/shm/vibra_lecture_bench.XXXXXX 2>/dev/null || mktemp -d)
trap 'rm -rf "$WORK"' EXIT
X264=(-c:v libx264 -preset veryfast -x264-params bframes=0:me=dia:subme=1:8x8dct=0 -crf 23 -g 150 -profile:v high -threads 2)

source bench/wall_time.sh  # seconds, median, alone, pair

lecture() { "$VIBRA" lecture "$STORY" --size "$DIMS" -q "$@"; }  # lecture [OPTIONS...] -o OUT
ours() { lecture "${OPTIONS[@]}" -o "$WORK/lecture.mp4"; }
ours >/dev/null 2>&1 || { ours; exit 1; }
w=${DIMS%x*} h=${DIMS#*x}
frames=$(ffprobe -v error -count_packets -select_streams v:0 -show_entries stream=nb_read_packets -of csv=p=0 "$WORK/lecture.mp4")
fps=$(ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate -of csv=p=0 "$WORK/lecture.mp4")
length=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$WORK/lecture.mp4")
megabytes=$(echo "$(stat -c %s "$WORK/lecture.mp4") / 1000000" | bc -l)
label="vibra lecture $(basename "$STORY") $DIMS${OPTIONS[*]:+ ${OPTIONS[*]}} ($frames frames, $(printf %.0f "$length") s, $(printf %.1f "$megabytes") MB)"

real_time() { printf "  -> %s: %.1fx real time, %.1f s (median)\n" "$1" "$(echo "$2 * $length / $frames" | bc -l)" \
                 "$(echo "$frames / $2" | bc -l)"; }
if (( ${#OPTIONS[@]} > 0 )); then  # the options against vibra's default setting, in turn
  default() { lecture -o "$WORK/default.mp4"; }
  PAIR_SAYS="with ${OPTIONS[*]} / the default" pair "$frames" "$label" ours "vibra lecture, the default setting" default
  real_time "with ${OPTIONS[*]}" "$FPS_A"
  real_time "the default" "$FPS_B"
  exit 0
fi
if (( frames * w * h * 3 / 2 > 4 * 1024 * 1024 * 1024 )); then
  alone "$label" "$frames" ours
  real_time "vibra" "$MEDIAN_FPS"
  exit 0
fi
ffmpeg -v error -i "$WORK/lecture.mp4" -map 0:v:0 -f rawvideo -pix_fmt yuv420p -y "$WORK/raw.yuv"
theirs() {
  ffmpeg -v error -f rawvideo -pix_fmt yuv420p -s "$DIMS" -r "$fps" -i "$WORK/raw.yuv" "${X264[@]}" -f mp4 -y "$WORK/ceiling.mp4"
}
PAIR_SAYS="the lecture / x264 alone" pair "$frames" "$label" ours "ffmpeg CLI x264 encoder only, same frames" theirs
real_time "vibra" "$FPS_A"
